#pragma once
// Rigid-plastic softening hinge law (paper eqs 34-38): the hinge moment t and the
// rotation jump alpha obey
//   phi(t, xi) = |t| - C(xi) <= 0,  C(xi) = max(Mu + Ks*xi, 0),  Ks < 0,
//   d(alpha) = d(gamma)*sign(t),  d(xi) = d(gamma),
// so on loading t = sign*(Mu + Ks*xi) until the capacity is zero at
// xi = Mu/|Ks|: from then on the hinge is free (t = 0). Below the capacity the
// hinge is rigid (alpha does not change). Units: moments in force*length, Ks in
// force*length per radian, alpha in radians.
#include "core/Error.h"

namespace c2d {

struct SofteningState {
  double alpha = 0;  // rotation jump (rad)
  double xi = 0;     // softening variable, accumulated |alpha|
};

struct SofteningResponse {
  double t = 0;         // hinge moment
  double tangent = 0;   // dt/d(trialMoment), see returnMap
  SofteningState state; // trial history
  bool loading = false; // the jump grew in this step
  bool failed = false;  // capacity exhausted: a free hinge
};

class LinearSoftening {
 public:
  // Requires Mu > 0 and Ks < 0; throws std::invalid_argument otherwise.
  LinearSoftening(double Mu, double Ks);

  double Mu() const { return Mu_; }
  double Ks() const { return Ks_; }
  double capacity(double xi) const;                        // C(xi)
  double failureJump() const { return Mu_ / -Ks_; }        // xi at which C = 0
  bool exhausted(double xi) const { return capacity(xi) <= 0; }

  // The hinge in series with an elastic spring of stiffness k (the bulk of the
  // element: k = EI/l_e). With the jump held at its committed value the spring
  // carries trialMoment; a jump increment d(alpha) lowers it by k*d(alpha):
  //   t = trialMoment - k*(alpha - alpha_n).
  // Solves that equation with the hinge law in closed form. tangent = dt/d(trialMoment):
  // 1 (rigid), Ks/(k + Ks) (softening), 0 (free). Fails unless k + Ks > 0 when the
  // hinge can still soften (otherwise the local equation has no unique solution).
  // A trial moment at the capacity to round-off (relative 1e-8) counts as loading
  // with a zero increment: a hinge at its capacity is taken to go on softening,
  // which makes the tangent of a just activated or committed softening state
  // the one of continued failure.
  Status returnMap(const SofteningState& committed, double trialMoment, double k,
                   SofteningResponse& out) const;

 private:
  double Mu_, Ks_;
};

}  // namespace c2d
