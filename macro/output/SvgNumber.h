#pragma once
// A coordinate or length in an SVG picture: two decimals, trailing zeros and a
// negative zero dropped, non-finite values as 0, magnitudes clamped to 1e7 px.
// A value labelled on an axis of a given span: rounded to 1e-4 of the span's
// decade, so that a footprint's edge moved by a micrometre (JITTer) reads 0,
// not -9e-07.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "macro/output/NumberText.h"

namespace c2d {

inline std::string px(double v) {
  if (!std::isfinite(v)) v = 0;
  v = std::clamp(v, -1e7, 1e7);
  std::string s = formatNumber("%.2f", v);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s;
}

inline double onAxis(double v, double span) {
  if (!std::isfinite(v) || !(span > 0) || !std::isfinite(span)) return v;
  const double step = std::pow(10.0, std::floor(std::log10(span)) - 4);
  const double r = std::round(v / step) * step;
  return r == 0 ? 0.0 : r;
}

}  // namespace c2d
