#include "materials/BilinearHardening.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace c2d {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kYieldTol = 1e-12;  // relative round-off band of the yield condition
}

BilinearHardening::BilinearHardening(double EI, double Mc, double My, double Kh1, double Kh2)
    : EI_(EI), Mc_(Mc), My_(My), Kh1_(Kh1), Kh2_(Kh2), xiY_(0) {
  if (!(EI > 0)) throw std::invalid_argument("bending stiffness EI must be positive");
  if (Mc == kInf) {  // elastic bending
    My_ = kInf;
    return;
  }
  if (!(Mc > 0) || !(My >= Mc))
    throw std::invalid_argument("hardening moments need 0 < Mc <= My (Mc = " + std::to_string(Mc) +
                                ", My = " + std::to_string(My) + ")");
  if (My > Mc && !(Kh1 > 0))
    throw std::invalid_argument("hardening modulus Kh1 must be positive when My > Mc");
  if (!(Kh2 > -EI)) throw std::invalid_argument("hardening modulus Kh2 must exceed -EI");
  xiY_ = My > Mc ? (My - Mc) / Kh1 : 0.0;
}

BilinearHardening BilinearHardening::elastic(double EI) { return {EI, kInf, kInf, 0, 0}; }

double BilinearHardening::yieldRadius(double xi) const {
  if (xi <= xiY_) return Mc_ + Kh1_ * xi;
  return My_ + Kh2_ * (xi - xiY_);
}

double BilinearHardening::hardeningAt(double moment) const {
  if (moment <= Mc_) return 0;
  if (moment <= My_) return (moment - Mc_) / Kh1_;
  if (Kh2_ > 0) return xiY_ + (moment - My_) / Kh2_;
  return kInf;
}

BendingResponse BilinearHardening::returnMap(const BendingState& committed, double kappa) const {
  BendingResponse r;
  r.state = committed;
  const double mTrial = EI_ * (kappa - committed.kp);
  const double phiTrial = std::abs(mTrial) - yieldRadius(committed.xi);
  if (!(phiTrial > kYieldTol * yieldRadius(committed.xi))) {  // elastic (loading below the yield radius or unloading)
    r.M = mTrial;
    r.tangent = EI_;
    return r;
  }
  // Plastic: |M| = |mTrial| - EI*dg = R(xi_n + dg), R piecewise linear in xi.
  // Try the first hardening branch, then the second.
  const double sign = mTrial > 0 ? 1.0 : -1.0;
  double dg = 0, kh = Kh2_;
  bool onFirst = false;
  if (committed.xi < xiY_) {
    dg = phiTrial / (EI_ + Kh1_);
    onFirst = committed.xi + dg <= xiY_;
    kh = Kh1_;
  }
  if (!onFirst) {
    // Second branch line R2(xi) = My + Kh2*(xi - xiY) extended to xi_n.
    const double r2 = My_ + Kh2_ * (committed.xi - xiY_);
    dg = (std::abs(mTrial) - r2) / (EI_ + Kh2_);
    kh = Kh2_;
  }
  r.state.kp = committed.kp + sign * dg;
  r.state.xi = committed.xi + dg;
  r.M = mTrial - sign * EI_ * dg;
  r.tangent = EI_ * kh / (EI_ + kh);
  r.plastic = true;
  r.secondBranch = !onFirst;
  return r;
}

}  // namespace c2d
