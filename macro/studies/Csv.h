#pragma once
// The CSV text of the study tables (plans, ensemble, batch): cells separated
// by commas, a cell quoted when it holds a comma, a quote or a line break.
#include <istream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace c2d {

// A CSV cell: quoted when it holds a comma, a quote or a line break.
std::string csvCell(const std::string& text);
// Appends ',' and the cell (as given: quote it with csvCell when it may need it).
inline void appendCell(std::string& row, std::string_view cell) {
  row += ',';
  row += cell;
}
// The cells of one line (quoted cells may hold commas and doubled quotes; a
// carriage return is dropped).
std::vector<std::string> splitCsv(const std::string& line);
// The next line of a table that is not empty, its carriage return dropped;
// lineNo counts every line read. False at the end.
bool nextTableLine(std::istream& in, std::string& line, int& lineNo);
// The finite number a whole cell holds (strtod's forms; a subnormal such as
// 1e-310 too, as the tables write it), or nothing: empty, text, a number
// followed by other characters, inf, nan, or beyond the range of a double.
std::optional<double> numberCell(const std::string& cell);
// The whole number a cell holds, or nothing.
std::optional<long long> integerCell(const std::string& cell);
// The whole number a cell (or a count in a file name) holds when it lies in
// [lo, hi], or nothing: every count read from a file is checked so.
std::optional<int> countCell(const std::string& cell, int lo, int hi);

}  // namespace c2d
