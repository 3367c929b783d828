#include "ballast/solution_text.h"

#include "ballast/ballast_messages.h"

#include <cstdio>
#include <cstdlib>

namespace auv::ballast {
namespace {

std::string format(const char* fmt, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

std::string join(const std::vector<std::string>& parts) {
  std::string out;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (i > 0) out += (i + 1 == parts.size()) ? " and " : ", ";
    out += parts[i];
  }
  return out;
}

}  // namespace

std::string kgText(double kg) { return format("%.2f kg", kg); }
std::string signedKgText(double kg) { return format("%+.2f kg", kg); }
std::string degText(double deg) { return format("%.2f\u00b0", deg); }
std::string signedDegText(double deg) { return format("%+.2f\u00b0", deg); }
std::string sizeText(double kg) { return format("%g kg", kg); }

Message pointNote(const AdjustmentPoint& point, const std::vector<double>& sizes_kg, const int* delta,
                  double before_kg, double after_kg) {
  std::vector<std::string> adds, removes;
  for (std::size_t s = sizes_kg.size(); s-- > 0;) {  // largest first, as they are handled
    if (delta[s] == 0) continue;
    const std::string item = std::to_string(std::abs(delta[s])) + " \u00d7 " + sizeText(sizes_kg[s]);
    (delta[s] > 0 ? adds : removes).push_back(item);
  }
  const std::string who = point.label.empty() ? point.name : point.label;
  if (adds.empty() && removes.empty()) return Message(msg::kPointNoChange, {who, kgText(before_kg)});
  std::string what;
  if (!removes.empty()) what = "remove " + join(removes);
  if (!adds.empty()) what += (what.empty() ? "add " : ", then add ") + join(adds);
  std::string english = who + ": " + what + " (" + signedKgText(after_kg - before_kg) + "; " + kgText(before_kg) +
                        " -> " + kgText(after_kg) + " of " + kgText(point.capacity_kg) + ").";
  std::vector<std::string> args{who,
                                signedKgText(after_kg - before_kg),
                                kgText(before_kg),
                                kgText(after_kg),
                                kgText(point.capacity_kg),
                                std::to_string(removes.size())};
  args.insert(args.end(), removes.begin(), removes.end());
  args.insert(args.end(), adds.begin(), adds.end());
  return Message(msg::kPointId, std::move(english), std::move(args));
}

}  // namespace auv::ballast
