#include "solvers/ProportionalLoad.h"

#include <cmath>

#include "core/io/Checkpoint.h"

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

void ProportionalLoad::write(std::ostream& out) const {
  using namespace checkpoint;
  put(out, kind_);
  put(out, k_);
  put(out, tmin_);
  put(out, tmax_);
  putDoubles(out, a_.data(), a_.size());
  putCount(out, points_.size());
  for (const auto& [t, p] : points_) {
    put(out, t);
    put(out, p);
  }
}

ProportionalLoad ProportionalLoad::read(std::istream& in) {
  using namespace checkpoint;
  ProportionalLoad p;
  p.kind_ = get<Kind>(in);
  if (p.kind_ != Kind::Ramp && p.kind_ != Kind::Formula && p.kind_ != Kind::Table)
    throw CheckpointError("unknown proportional load kind");
  p.k_ = get<int>(in);
  p.tmin_ = get<double>(in);
  p.tmax_ = get<double>(in);
  getDoubles(in, p.a_.data(), p.a_.size());
  p.points_.resize(getCount(in));
  for (auto& [t, v] : p.points_) {
    t = get<double>(in);
    v = get<double>(in);
  }
  return p;
}

}  // namespace c2d
