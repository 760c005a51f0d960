#pragma once
// Stress-resultant bending plasticity with bilinear isotropic hardening (paper eqs 8-13).
//
// Moment-curvature (monotonic): elastic with EI up to Mc, then hardening modulus
// Kh1 (slope of M against plastic curvature) up to My, Kh2 beyond. The yield
// radius in terms of the hardening variable xi (accumulated |plastic curvature|):
//   R(xi) = Mc + Kh1*xi                  for xi <= xiY = (My - Mc)/Kh1,
//   R(xi) = My + Kh2*(xi - xiY)          beyond,
// which is eq 11 written as R = Mc - q. Units: moments in force*length,
// curvatures in 1/length, EI and Kh in force*length^2.
#include <limits>

namespace c2d {

// Value-type history of one bending section.
struct BendingState {
  double kp = 0;  // plastic curvature
  double xi = 0;  // hardening variable (accumulated plastic curvature magnitude)
};

struct BendingResponse {
  double M = 0;        // bending moment
  double tangent = 0;  // consistent tangent dM/dkappa
  BendingState state;  // trial history
  bool plastic = false;  // the step loaded plastically
  bool secondBranch = false;  // plastic on the branch beyond My (modulus Kh2)
};

class BilinearHardening {
 public:
  // Requires EI > 0, 0 < Mc <= My, Kh1 > 0 when My > Mc, Kh2 > -EI; throws std::invalid_argument otherwise.
  BilinearHardening(double EI, double Mc, double My, double Kh1, double Kh2);
  // Elastic bending: the yield moment is infinite.
  static BilinearHardening elastic(double EI);

  double EI() const { return EI_; }
  double Mc() const { return Mc_; }
  double My() const { return My_; }
  bool isElastic() const { return Mc_ == std::numeric_limits<double>::infinity(); }

  double yieldRadius(double xi) const;  // R(xi)
  // Smallest hardening variable at which the yield radius reaches `moment`
  // (0 when moment <= Mc); infinity when the radius never gets there.
  double hardeningAt(double moment) const;
  // Closed-form return map (the law is piecewise linear: no iterations) from the
  // committed state to the total curvature kappa. Kuhn-Tucker conditions hold.
  // A trial state on the yield surface to round-off (relative 1e-12) counts as
  // elastic, so that a committed plastic state gives the elastic (unloading)
  // tangent at its own curvature.
  BendingResponse returnMap(const BendingState& committed, double kappa) const;

 private:
  double EI_, Mc_, My_, Kh1_, Kh2_;
  double xiY_;  // hardening variable at which R reaches My
};

}  // namespace c2d
