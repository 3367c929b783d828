#pragma once
// Advice for a person (notes, warnings, explanations) as data: a stable id,
// its arguments (already formatted: numbers with their units, names) and the
// English sentence the command line prints.
//
// A Message *is* its English sentence (it derives from std::string), so the
// CLI text, the JSON and every reader of `notes` see exactly what they saw
// before ids existed; a front end that translates looks up `id()` and fills
// its own sentence with `args()` (ui/wizard/advice_text.*). A Message built
// from a plain string has no id and is shown as it is.
#include <string>
#include <vector>

namespace auv {

// One kind of advice: its id ("analysis.no_depth_cmd") and English format
// with %1..%99 for the arguments.
struct MessageFormat {
  const char* id;
  const char* english;
};

class Message : public std::string {
 public:
  Message() = default;
  Message(std::string text) : std::string(std::move(text)) {}  // NOLINT: a sentence without an id
  Message(const char* text) : std::string(text) {}             // NOLINT
  Message(const MessageFormat& f, std::vector<std::string> args = {});
  // A sentence whose English is built in pieces (not one format): its id,
  // the English as built, and the arguments a translation needs.
  Message(std::string id, std::string english, std::vector<std::string> args)
      : std::string(std::move(english)), id_(std::move(id)), args_(std::move(args)) {}

  const std::string& id() const { return id_; }
  const std::vector<std::string>& args() const { return args_; }
  const std::string& text() const { return *this; }

 private:
  std::string id_;
  std::vector<std::string> args_;
};

// `format` with %1..%99 replaced by args[0..98] ("%%" is a literal '%').
std::string formatMessage(const std::string& format, const std::vector<std::string>& args);

// How many distinct %n a format uses (the arguments it needs).
int messageArgCount(const std::string& format);

}  // namespace auv
