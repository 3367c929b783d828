#include "missionlog/detail/line_cells.h"

#include "missionlog/detail/ascii_text.h"

namespace auv::detail {
namespace {

// dd.mm.yyyy or yyyy-mm-dd
bool looksLikeDate(std::string_view t) {
  if (t.size() != 10) return false;
  const bool dmy = t[2] == '.' && t[5] == '.' && isDigit(t[0]) && isDigit(t[1]) && isDigit(t[3]) && isDigit(t[4]) &&
                   isDigit(t[6]) && isDigit(t[9]);
  const bool ymd = t[4] == '-' && t[7] == '-' && isDigit(t[0]) && isDigit(t[3]) && isDigit(t[5]) && isDigit(t[8]);
  return dmy || ymd;
}

bool looksLikeClock(std::string_view t) {
  return t.size() >= 4 && isDigit(t[0]) && (t[1] == ':' || (isDigit(t[1]) && t[2] == ':'));
}

}  // namespace

void splitAt(std::string_view line, char delim, std::vector<Cell>& out) {
  out.clear();
  if (line.find('"') == std::string_view::npos) {
    std::size_t start = 0;
    for (;;) {
      const auto p = line.find(delim, start);
      if (p == std::string_view::npos) {
        out.push_back({line.substr(start), start});
        return;
      }
      out.push_back({line.substr(start, p - start), start});
      start = p + 1;
    }
  }
  std::size_t start = 0;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '"') quoted = !quoted;
    else if (line[i] == delim && !quoted) {
      out.push_back({line.substr(start, i - start), start});
      start = i + 1;
    }
  }
  out.push_back({line.substr(start), start});
}

std::string describe(Mode m) {
  switch (m.delim) {
    case ',': return "comma";
    case ';': return "semicolon";
    case '\t': return "tab";
    default: return m.joinDateTime ? "whitespace (date and time joined)" : "whitespace";
  }
}

void splitBlanks(std::string_view line, std::vector<Cell>& out) {
  out.clear();
  std::size_t i = 0;
  const std::size_t n = line.size();
  while (i < n) {
    while (i < n && (line[i] == ' ' || line[i] == '\t')) ++i;
    if (i >= n) break;
    const std::size_t s = i;
    while (i < n && line[i] != ' ' && line[i] != '\t') ++i;
    out.push_back({line.substr(s, i - s), s});
  }
}

void splitLine(std::string_view line, Mode mode, bool header, std::vector<Cell>& out) {
  if (mode.delim) {
    splitAt(line, mode.delim, out);
    return;
  }
  splitBlanks(line, out);
  // Joins in place, each cell onto the (possibly already joined) one before.
  std::size_t w = 0;
  for (std::size_t r = 0; r < out.size(); ++r) {
    const Cell tok = out[r];
    if (w > 0) {
      Cell& prev = out[w - 1];
      const bool join = header ? (tok.text.front() == '(' || tok.text.front() == '[' || tok.text.front() == '{')
                               : (mode.joinDateTime && looksLikeDate(prev.text) && looksLikeClock(tok.text));
      if (join) {
        prev.text = line.substr(prev.offset, tok.offset + tok.text.size() - prev.offset);
        continue;
      }
    }
    out[w++] = tok;
  }
  out.resize(w);
}

std::string_view unquoted(std::string_view c) {
  c = trim(c);
  if (c.size() >= 2 && c.front() == '"' && c.back() == '"') c = trim(c.substr(1, c.size() - 2));
  return c;
}

bool isComment(std::string_view t) {
  return !t.empty() && (t.front() == '#' || t.front() == '%' || t.substr(0, 2) == "//");
}

}  // namespace auv::detail
