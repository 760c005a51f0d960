#pragma once
// FEAP's proportional load tables (PROP): the factor that multiplies FORCe and
// DISPlacement values as a function of time.
//   Ramp:   p = t (PROP with a blank data record)
//   Type 1: p = a1 + a2*tau + a3*sin(a4*tau + a5)^k, tau = t - tmin, on [tmin, tmax], else 0
//   Type 2: piecewise linear through (t_i, p_i); constant beyond the ends
#include <array>
#include <istream>
#include <ostream>
#include <utility>
#include <vector>

namespace c2d {

class ProportionalLoad {
 public:
  static ProportionalLoad ramp();
  static ProportionalLoad formula(int k, double tmin, double tmax, const std::array<double, 5>& a);
  static ProportionalLoad table(std::vector<std::pair<double, double>> points);

  double operator()(double t) const;

  // Restart files (core/io/Checkpoint.h): the table as raw values.
  void write(std::ostream& out) const;
  static ProportionalLoad read(std::istream& in);  // throws CheckpointError

 private:
  enum class Kind { Ramp, Formula, Table } kind_ = Kind::Ramp;
  int k_ = 1;
  double tmin_ = 0, tmax_ = 0;
  std::array<double, 5> a_{};
  std::vector<std::pair<double, double>> points_;
};

}  // namespace c2d
