#pragma once
// Frictionless penalty contact of every node with a rigid ground line y = y0
// (paper section 4, eqs 72-75). Penetration g = y0 - y >= 0 gives an upward
// force p = k g and the stored energy U = k <g>^2 / 2.
//
// With the mid-point scheme the force is the discrete gradient of U between t_n
// and t_n+1, so an impact conserves energy exactly (alpha = 0), plus the
// dissipative term alpha*k*(<g_n+1> - <g_n>) (eq 75; <.> the positive part, so
// that the force is continuous when a node enters or leaves contact).
#include "core/Model.h"
#include "core/StepRule.h"

namespace c2d {

struct ContactForce {
  double force = 0;    // upward force on the node (>= 0 unless dissipation pulls)
  double tangent = 0;  // d(force)/d(penetration at t_n+1): the stiffness on the node's v dof
};

// Penetration of a node at vertical position y.
inline double penetration(const Ground& g, double y) { return g.y0 - y; }
inline double contactEnergy(const Ground& g, double y) {
  const double p = penetration(g, y);
  return p > 0 ? 0.5 * g.k * p * p : 0.0;
}

// Force and its stiffness for the node's vertical position yn (t_n) and y (t_n+1)
// under the step rule; the ground's alpha, or the rule's when the ground gives none.
ContactForce groundContact(const Ground& g, double yn, double y, const StepRule& rule);

}  // namespace c2d
