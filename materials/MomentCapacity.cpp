#include "materials/MomentCapacity.h"

#include <stdexcept>

namespace c2d {

ScaledCapacity::ScaledCapacity(const std::array<MomentLaw, 2>& laws,
                               const std::vector<std::pair<double, double>>& curve)
    : laws_(laws) {
  if (curve.size() < 2) throw std::invalid_argument("an interaction curve needs two pairs N Mu or more");
  std::vector<double> n, mu;
  for (const auto& [N, M] : curve) {
    if (!(M > 0)) throw std::invalid_argument("the moments of an interaction curve must be positive");
    if (!n.empty() && !(N > n.back()))
      throw std::invalid_argument("the axial forces of an interaction curve must increase");
    n.push_back(N);
    mu.push_back(M);
  }
  curve_ = MonotoneCubic(std::move(n), std::move(mu));
  mu0_ = curve_(0.0);
}

double ScaledCapacity::factor(double N) const { return curve_(N) / mu0_; }

MomentLaw ScaledCapacity::at(int sign, double N) const {
  const MonotoneCubic::Value v = curve_.at(N);
  const double f = v.y / mu0_, df = v.dy / mu0_;
  const MomentLaw& b = laws_[sign > 0 ? 0 : 1];
  MomentLaw l = b;
  l.Mc = f * b.Mc;
  l.My = f * b.My;
  l.Kh1 = f * b.Kh1;
  l.Kh2 = f * b.Kh2;
  l.Mu = f * b.Mu;
  l.dMc = df * b.Mc;
  l.dMy = df * b.My;
  l.dKh1 = df * b.Kh1;
  l.dKh2 = df * b.Kh2;
  l.dMu = df * b.Mu;
  return l;
}

}  // namespace c2d
