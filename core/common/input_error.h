#pragma once
// The one exception type for bad operator or file input. It carries where the
// problem is and what to do about it, so every front end (CLI, GUI, tests) can
// print "file:line:column: field: problem; fix" without guessing.
#include <stdexcept>
#include <string>

namespace auv {

struct InputLocation {
  std::string file;   // empty for command-line or form input
  long line = 0;      // 1-based, 0 = not applicable
  long column = 0;    // 1-based, 0 = not applicable
};

class InputError : public std::runtime_error {
 public:
  InputError(std::string field, std::string problem, std::string fix,
             InputLocation where = {});

  const std::string& field() const { return field_; }
  const std::string& problem() const { return problem_; }
  const std::string& fix() const { return fix_; }
  const InputLocation& where() const { return where_; }

 private:
  std::string field_, problem_, fix_;
  InputLocation where_;
};

// "file:line:col: " prefix, or "" when there is no file.
std::string formatLocation(const InputLocation& where);

}  // namespace auv
