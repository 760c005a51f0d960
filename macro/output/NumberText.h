#pragma once
// A number as the program's text outputs write it (logs, CSV tables, file
// names, pictures): every output formats its numbers here.
#include <string>

namespace c2d {

// printf's format with one conversion of a double, e.g. "%.6e", "%.4g".
std::string formatNumber(const char* format, double v);

// The shortest text that reads back to the same double (0.1234567,
// 1.0000000000000002e+16, 1e-310): the values the study tables write.
std::string exactNumber(double v);

}  // namespace c2d
