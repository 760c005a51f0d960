#include "solvers/ProportionalLoad.h"

#include <cmath>

namespace c2d {

ProportionalLoad ProportionalLoad::ramp() { return {}; }

ProportionalLoad ProportionalLoad::formula(int k, double tmin, double tmax,
                                           const std::array<double, 5>& a) {
  ProportionalLoad p;
  p.kind_ = Kind::Formula;
  p.k_ = k;
  p.tmin_ = tmin;
  p.tmax_ = tmax;
  p.a_ = a;
  return p;
}

ProportionalLoad ProportionalLoad::table(std::vector<std::pair<double, double>> points) {
  ProportionalLoad p;
  p.kind_ = Kind::Table;
  p.points_ = std::move(points);
  return p;
}

double ProportionalLoad::operator()(double t) const {
  switch (kind_) {
    case Kind::Ramp:
      return t;
    case Kind::Formula: {
      if (t < tmin_ || t > tmax_) return 0.0;
      const double tau = t - tmin_;
      const double s = std::sin(a_[3] * tau + a_[4]);
      return a_[0] + a_[1] * tau + a_[2] * std::pow(s, k_);
    }
    case Kind::Table: {
      if (points_.empty()) return 0.0;
      if (t <= points_.front().first) return points_.front().second;
      if (t >= points_.back().first) return points_.back().second;
      for (size_t i = 1; i < points_.size(); ++i)
        if (t <= points_[i].first) {
          const auto& [t0, p0] = points_[i - 1];
          const auto& [t1, p1] = points_[i];
          return t1 > t0 ? p0 + (p1 - p0) * (t - t0) / (t1 - t0) : p1;
        }
      return points_.back().second;
    }
  }
  return 0.0;
}

}  // namespace c2d
