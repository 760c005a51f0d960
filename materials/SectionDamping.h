#pragma once
// Structural damping of a frame section (deck: DAMPing RAYLeigh 0 a1, or
// DAMPing RATIo zeta f, in a MATErial set): a Kelvin-Voigt dashpot in parallel
// with the section, stiffness proportional (the a1 K of Rayleigh's a0 M + a1 K;
// the mass term would brake rigid motion, a free fall among them). Its
// resultants are a1 C Edot, C = diag(EA, GA, EI), Edot the section's strain
// rate over the step, (E_n+1 - E_n)/h: a mode of circular frequency w has the
// damping ratio a1 w / 2 (rising with the frequency), rigid motions strain
// nothing and are not damped, and the coefficient does not depend on the step.
//
// With f = a1/h the dashpot adds f dE to the strains the resultants are taken
// from. Under the mid-point scheme, whose resultants come from the
// alpha-weighted strains, that is alpha + f in place of alpha: the element's
// work on the step is W_n+1 - W_n + (alpha + f) l dE.C.dE, the dashpot's part
// f l dE.C.dE >= 0 booked exactly as dissipated. Under Newmark the dashpot's
// force is taken at t_n+1 with the same rate (first order in h; its work on
// the step is f l dE.C.dE for the geometrically linear elements). Statics: none.
//
// Bending with the hinge laws (materials/HingedBending): the dashpot acts on the
// elastic curvature's change dKe = dM/EI over the step, not on the plastic
// curvature or the hinge's rotation jump. On the total curvature it would make
// a fast-turning hinge stronger by a1 EI omega / l (a hinge's jump is a
// curvature alpha/l: the shorter the element, the stronger), a moment near Mu
// at the turning rates of a collapse. Paired with the element's curvature
// change dK, the moment
//   m = f EI s^2 dK,  s = dKe/dK = dM/(EI dK) clipped to [0, 1],
// does the work f l EI (s dK)^2 >= 0: the Kelvin-Voigt moment f EI dK in an
// elastic step (s = 1), less while the section hardens (s = Kh/(EI + Kh)),
// nothing while a hinge softens (its moment falls as the curvature grows).
#include "core/StepRule.h"

namespace c2d {

class SectionDamping {
 public:
  SectionDamping() = default;
  // a1: the stiffness-proportional coefficient (time units, s), >= 0.
  explicit SectionDamping(double a1) : a1_(a1) {}

  double coefficient() const { return a1_; }
  bool active() const { return a1_ > 0; }

  // f = a1/h for a dynamic step of length h; 0 in statics or without damping.
  double factor(const StepRule& rule) const {
    return a1_ > 0 && rule.dynamic() ? a1_ / rule.h : 0.0;
  }

  // The dashpot's bending moment over a step and its derivative with respect
  // to the curvature at t_n+1: factor f, bending stiffness EI, the moment's
  // change dM over the curvature's change dK, and kt1 = dM_n+1/dK_n+1; dM1 =
  // dm/dM_n+1 at fixed curvature (a moment that follows the axial force:
  // dm/dN = dM1 dM_n+1/dN).
  //
  // The same dashpot acts on the axial strain of a member whose axial force is
  // bounded (materials/AxialCapacity): there the elastic strain's change is
  // dEe = dE - dEp, and bending(f, EA, EA dEe, dE, EA dEe'/dE_n+1) with EA
  // the stiffness of the committed branch (AxialCapacity::damping) gives the
  // force f EA s^2 dE,
  // s = dEe/dE clipped to [0, 1]: the Kelvin-Voigt force in an elastic step,
  // nothing while the bars yield at a fixed force or the section crushes.
  struct Bending {
    double m = 0, tangent = 0, dM1 = 0;
  };
  static Bending bending(double f, double EI, double dM, double dK, double kt1);
  // An elastic section's (dM = EI dK): the Kelvin-Voigt moment.
  static Bending elasticBending(double f, double EI, double dK) {
    return {f * EI * dK, f * EI, 0};
  }

 private:
  double a1_ = 0;
};

}  // namespace c2d
