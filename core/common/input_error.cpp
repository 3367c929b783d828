#include "common/input_error.h"

namespace auv {
namespace {
std::string compose(const std::string& field, const std::string& problem,
                    const std::string& fix, const InputLocation& where) {
  std::string s = formatLocation(where);
  if (!field.empty()) s += field + ": ";
  s += problem;
  if (!fix.empty()) s += "; " + fix;
  return s;
}
}  // namespace

InputError::InputError(std::string field, std::string problem, std::string fix,
                       InputLocation where)
    : std::runtime_error(compose(field, problem, fix, where)),
      field_(std::move(field)),
      problem_(std::move(problem)),
      fix_(std::move(fix)),
      where_(std::move(where)) {}

std::string formatLocation(const InputLocation& where) {
  if (where.file.empty()) return {};
  std::string s = where.file;
  if (where.line > 0) s += ":" + std::to_string(where.line);
  if (where.column > 0) s += ":" + std::to_string(where.column);
  return s + ": ";
}

}  // namespace auv
