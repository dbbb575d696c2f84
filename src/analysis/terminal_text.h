// What the commands print on a terminal, fitted to kTerminalWidth columns without dropping a word:
// long lines wrapped at spaces under their own second column, tables aligned with their headers
// stacked over several lines and, where still too wide, split into parts that each repeat the
// first column. Pure text functions, so the width test calls them on any command's output.
#pragma once
#include <string>
#include <vector>

namespace dsr {

// The widest line a command's normal output holds.
constexpr size_t kTerminalWidth = 120;

// Every line of `text` longer than `width` wrapped at spaces. A continuation line starts under
// the line's second column where the line has one ("  key      value ...": the value's column,
// when it lies in the left half), else four columns in from the line's own indent. A word longer
// than a whole line is cut at the width (the rest follows on the next line), never dropped.
std::string wrap_lines(const std::string& text, size_t width = kTerminalWidth);

// An aligned table: a column per header, right-aligned where `right` says so (missing: left).
// Each header is stacked over as many lines as make its column no wider than its widest cell (at
// least its longest word). A table wider than `width` is printed in parts, each repeating the first
// column, the parts separated by a blank line. `indent` spaces before every line.
std::string text_table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows,
                       const std::vector<bool>& right = {}, size_t width = kTerminalWidth, size_t indent = 0);

// Markdown as a terminal shows it: every block of table lines ("| a | b |", its "|---|" line
// marking the header) as text_table (columns right-aligned where the markdown says ---:), every
// other line as wrap_lines.
std::string markdown_for_terminal(const std::string& markdown, size_t width = kTerminalWidth);

// A loader's warning to stderr as "warning: TEXT", wrapped like the rest of the output: the
// warning printer both programs install (scene.h set_warning_printer).
void print_wrapped_warning(const std::string& warning);

// The lines of `text` longer than `width` columns (counted in UTF-8 characters), for tests.
std::vector<std::string> lines_over(const std::string& text, size_t width = kTerminalWidth);

}  // namespace dsr
