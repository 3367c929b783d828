#include "common/message.h"

#include <algorithm>

namespace auv {

Message::Message(const MessageFormat& f, std::vector<std::string> args)
    : std::string(formatMessage(f.english, args)), id_(f.id), args_(std::move(args)) {}

std::string formatMessage(const std::string& format, const std::vector<std::string>& args) {
  std::string out;
  out.reserve(format.size() + 16 * args.size());
  for (std::size_t i = 0; i < format.size(); ++i) {
    const char c = format[i];
    if (c == '%' && i + 1 < format.size()) {
      const char n = format[i + 1];
      if (n == '%') {
        out += '%';
        ++i;
        continue;
      }
      if (n >= '1' && n <= '9') {
        // Two digits when the format has them and there are that many arguments.
        std::size_t k = static_cast<std::size_t>(n - '0');
        std::size_t used = 1;
        if (i + 2 < format.size() && format[i + 2] >= '0' && format[i + 2] <= '9') {
          const std::size_t k2 = k * 10 + static_cast<std::size_t>(format[i + 2] - '0');
          if (k2 <= args.size()) k = k2, used = 2;
        }
        out += k <= args.size() ? args[k - 1] : format.substr(i, used + 1);
        i += used;
        continue;
      }
    }
    out += c;
  }
  return out;
}

int messageArgCount(const std::string& format) {
  int most = 0;
  for (std::size_t i = 0; i + 1 < format.size(); ++i) {
    if (format[i] != '%') continue;
    const char n = format[i + 1];
    if (n == '%') {
      ++i;
    } else if (n >= '1' && n <= '9') {
      int k = n - '0';
      if (i + 2 < format.size() && format[i + 2] >= '0' && format[i + 2] <= '9') k = k * 10 + (format[i + 2] - '0');
      most = std::max(most, k);
    }
  }
  return most;
}

}  // namespace auv
