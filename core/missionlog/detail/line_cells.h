#pragma once
// Lines of text tables split into cells, shared by the interchange CSV and the
// delimited-text readers. Cells are views into the line with their byte
// offset, so that a message can name the character column.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace auv::detail {

struct Cell {
  std::string_view text;
  std::size_t offset = 0;  // 0-based byte offset in the line
};

// Splits at `delim`; a delimiter inside double quotes does not split.
void splitAt(std::string_view line, char delim, std::vector<Cell>& out);

// Splits at runs of blanks and tabs; no empty cells.
void splitBlanks(std::string_view line, std::vector<Cell>& out);

// How the delimited-text reader splits a line.
struct Mode {
  char delim = ',';  // 0 = runs of blanks
  bool joinDateTime = false;
};

// "comma", "semicolon", "tab", "whitespace", for messages and format labels.
std::string describe(Mode m);

// Splits by `mode`. With runs of blanks, a header cell that starts with a
// bracket joins the cell before it ("depth (m)"), and a row's date and clock
// cells join when `mode.joinDateTime` ("24.06.2016 14:31:11").
void splitLine(std::string_view line, Mode mode, bool header, std::vector<Cell>& out);

// Without blanks and one pair of surrounding double quotes.
std::string_view unquoted(std::string_view cell);

// A vendor-log comment line (already trimmed): '#', '%' or '//'.
bool isComment(std::string_view trimmed);

}  // namespace auv::detail
