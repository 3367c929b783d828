#pragma once
// Every reader notes a problem the same way: build a ReadProblem and let the
// report keep the first options.max_problems_per_kind of its kind.
#include <string>
#include <string_view>
#include <utility>

#include "missionlog/detail/ascii_text.h"
#include "missionlog/log_table.h"
#include "missionlog/read_options.h"
#include "missionlog/read_report.h"

namespace auv::detail {

inline void reportProblem(ReadReport& report, const ReadOptions& options, ReadProblemKind kind,
                          InputLocation where, std::string column, std::string what, std::string fix) {
  ReadProblem p;
  p.kind = kind;
  p.where = std::move(where);
  p.column = std::move(column);
  p.problem = std::move(what);
  p.fix = std::move(fix);
  report.add(std::move(p), options.max_problems_per_kind);
}

// A cell as a message quotes it: 'text', trimmed, escaped and capped.
inline std::string quotedCell(std::string_view cell) {
  std::string out = "'";
  out += printableText(trim(cell));
  out += '\'';
  return out;
}

}  // namespace auv::detail
