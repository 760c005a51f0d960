#include "materials/MonotoneCubic.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace c2d {

namespace {

// The end slope of Fritsch and Butland's three-point formula, limited so that
// the end interval stays monotone.
double endSlope(double h0, double h1, double s0, double s1) {
  double d = ((2 * h0 + h1) * s0 - h0 * s1) / (h0 + h1);
  if (d * s0 <= 0) return 0;
  if (s0 * s1 <= 0 && std::abs(d) > std::abs(3 * s0)) d = 3 * s0;
  return d;
}

}  // namespace

MonotoneCubic::MonotoneCubic(std::vector<double> x, std::vector<double> y)
    : x_(std::move(x)), y_(std::move(y)) {
  const std::size_t n = x_.size();
  if (n < 2 || y_.size() != n) throw std::invalid_argument("monotone cubic: needs two points or more");
  for (std::size_t i = 1; i < n; ++i)
    if (!(x_[i] > x_[i - 1])) throw std::invalid_argument("monotone cubic: abscissae must increase");
  std::vector<double> h(n - 1), s(n - 1);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    h[i] = x_[i + 1] - x_[i];
    s[i] = (y_[i + 1] - y_[i]) / h[i];
  }
  d_.assign(n, 0.0);
  if (n == 2) {
    d_[0] = d_[1] = s[0];
    return;
  }
  for (std::size_t i = 1; i + 1 < n; ++i) {
    if (s[i - 1] * s[i] <= 0) continue;  // a local extremum (or flat): slope zero
    const double w1 = 2 * h[i] + h[i - 1], w2 = h[i] + 2 * h[i - 1];
    d_[i] = (w1 + w2) / (w1 / s[i - 1] + w2 / s[i]);
  }
  d_[0] = endSlope(h[0], h[1], s[0], s[1]);
  d_[n - 1] = endSlope(h[n - 2], h[n - 3], s[n - 2], s[n - 3]);
}

MonotoneCubic::Value MonotoneCubic::at(double x) const {
  const std::size_t n = x_.size();
  if (n == 0) return {};
  if (x <= x_.front()) return {y_.front(), 0.0};
  if (x >= x_.back()) return {y_.back(), 0.0};
  const std::size_t i =
      static_cast<std::size_t>(std::upper_bound(x_.begin(), x_.end(), x) - x_.begin()) - 1;
  const double h = x_[i + 1] - x_[i], t = (x - x_[i]) / h;
  const double t2 = t * t, t3 = t2 * t;
  const double h00 = 2 * t3 - 3 * t2 + 1, h10 = t3 - 2 * t2 + t, h01 = -2 * t3 + 3 * t2,
               h11 = t3 - t2;
  const double y = h00 * y_[i] + h10 * h * d_[i] + h01 * y_[i + 1] + h11 * h * d_[i + 1];
  const double dh00 = 6 * t2 - 6 * t, dh10 = 3 * t2 - 4 * t + 1, dh01 = -6 * t2 + 6 * t,
               dh11 = 3 * t2 - 2 * t;
  const double dy = (dh00 * y_[i] + dh01 * y_[i + 1]) / h + dh10 * d_[i] + dh11 * d_[i + 1];
  return {y, dy};
}

}  // namespace c2d
