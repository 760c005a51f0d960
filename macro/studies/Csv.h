#pragma once
// The CSV text of the study tables (plans, ensemble, batch): cells separated
// by commas, a cell quoted when it holds a comma, a quote or a line break.
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
// The number a whole cell holds (strtod's forms), or nothing: empty, text, or
// a number followed by other characters.
std::optional<double> numberCell(const std::string& cell);
// The whole number a cell holds, or nothing.
std::optional<long long> integerCell(const std::string& cell);

}  // namespace c2d
