#pragma once
// A coordinate or length in an SVG picture: two decimals, trailing zeros and a
// negative zero dropped, non-finite values as 0, magnitudes clamped to 1e7 px.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace c2d {

inline std::string px(double v) {
  if (!std::isfinite(v)) v = 0;
  v = std::clamp(v, -1e7, 1e7);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  std::string s(buf);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s;
}

}  // namespace c2d
