#include "macro/studies/Csv.h"

#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdlib>

namespace c2d {

std::string csvCell(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

std::vector<std::string> splitCsv(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cells.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        cells.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      cells.emplace_back();
    } else if (c != '\r') {
      cells.back() += c;
    }
  }
  return cells;
}

std::optional<double> numberCell(const std::string& cell) {
  if (cell.empty() || cell.front() == ' ') return std::nullopt;
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(cell.c_str(), &end);
  if (end != cell.c_str() + cell.size() || !std::isfinite(v)) return std::nullopt;
  // ERANGE on underflow: strtod gives the subnormal (or zero) nearest, which is
  // what the text means; on overflow it gives HUGE_VAL (not finite, above).
  if (errno == ERANGE && std::fabs(v) > DBL_MIN) return std::nullopt;
  return v;
}

std::optional<int> countCell(const std::string& cell, int lo, int hi) {
  const auto v = integerCell(cell);
  if (!v || *v < lo || *v > hi) return std::nullopt;
  return static_cast<int>(*v);
}

std::optional<long long> integerCell(const std::string& cell) {
  if (cell.empty() || cell.front() == ' ') return std::nullopt;
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(cell.c_str(), &end, 10);
  if (end != cell.c_str() + cell.size() || errno == ERANGE) return std::nullopt;
  return v;
}

bool nextTableLine(std::istream& in, std::string& line, int& lineNo) {
  while (std::getline(in, line)) {
    ++lineNo;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (!line.empty()) return true;
  }
  return false;
}

}  // namespace c2d
