#pragma once
// A number in the run's log: printf's format (one conversion), e.g. "%.6e".
#include <cstdio>
#include <string>

namespace c2d {

inline std::string logNumber(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

}  // namespace c2d
