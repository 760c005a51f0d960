#pragma once
// Monotone piecewise cubic Hermite interpolation (Fritsch and Carlson 1980,
// with the weighted harmonic mean slopes of Fritsch and Butland 1984) of a
// table y(x) on increasing abscissae: the interpolant is C1, passes through
// the nodes, keeps the data's monotonicity on every interval and has no
// overshoot (a maximum of the data stays at its node). Outside the table the
// end values hold (derivative zero).
#include <vector>

namespace c2d {

class MonotoneCubic {
 public:
  MonotoneCubic() = default;
  // x strictly increasing, y of the same size (at least 2 points); throws
  // std::invalid_argument otherwise.
  MonotoneCubic(std::vector<double> x, std::vector<double> y);

  // Value and derivative dy/dx at x.
  struct Value {
    double y = 0, dy = 0;
  };
  Value at(double x) const;
  double operator()(double x) const { return at(x).y; }

  const std::vector<double>& x() const { return x_; }
  const std::vector<double>& y() const { return y_; }

 private:
  std::vector<double> x_, y_, d_;  // nodes, values, node slopes
};

}  // namespace c2d
