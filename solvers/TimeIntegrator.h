#pragma once
// Time integrators. Each one is a rule for velocities and the inertia
// acceleration as affine functions of the displacement increment (core/StepRule.h);
// Newton only iterates, the elements apply the rule.
//
// Newmark(beta, gamma): a_n+1 = (d - d_n)/(beta dt^2) - v_n/(beta dt) - (1/(2 beta) - 1) a_n,
//   v_n+1 = v_n + dt((1 - gamma) a_n + gamma a_n+1).
// Mid-point energy conserving (alpha = beta = 0) / decaying (alpha, beta in (0, 1/2]),
//   paper section 3.3 with the corrected eq (61):
//   (d_n+1 - d_n)/dt = (v_n+1 + v_n)/2 + beta (v_n+1 - v_n),  a_eff = (v_n+1 - v_n)/dt,
//   and stress resultants from (1/2 + alpha) E_n+1 + (1/2 - alpha) E_n; a
//   rotation's increment enters as 2 tan(dtheta/2) (the Cayley rule: energy and
//   angular momentum conserved together, core/StepRule.h).
#include <string>

#include "core/StepRule.h"

namespace c2d {

struct TimeIntegrator {
  enum class Kind { Static, Newmark, MidPoint };
  Kind kind = Kind::Static;
  double beta = 0.25, gamma = 0.5;  // Newmark
  double alpha = 0, betaV = 0;      // mid-point: strain and velocity dissipation

  static TimeIntegrator statics() { return {}; }
  static TimeIntegrator newmark(double beta, double gamma);
  static TimeIntegrator midPoint(double alpha, double beta);

  bool dynamic() const { return kind != Kind::Static; }
  StepRule rule(double dt) const;
  std::string describe() const;
};

}  // namespace c2d
