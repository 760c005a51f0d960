#pragma once
// The dashpot of a contact (the zeta of the GROUnd and MEMBers records): a
// viscous force c dp/dt on the penetration p while the contact touches (p
// beyond the set ps its crushing left, core/contact/CrushingLaw.h; 0 for an elastic
// contact), with c = 2 zeta sqrt(k m) the damping of ratio zeta for the mass m
// the contact moves (a node's own mass on the ground, core/NodeMass.h; the
// reduced mass of a node and a member's point for a member pair). A property
// of the contact, the same at every step: alone (e = 1) it lets a mass
// striking at v leave with exp(-pi zeta / sqrt(1 - zeta^2)) v (zeta < 1; like
// a linear Kelvin-Voigt contact the force may pull while the penetration
// shrinks).
//
// Mid-point scheme: f = c (<p_n+1 - ps> - <p_n - ps>) / h, the step's mean rate
// of the touching part of the penetration: its work over the step,
// c (<p_n+1 - ps> - <p_n - ps>)(p_n+1 - p_n) / h >= 0, is what it dissipates,
// and the force is continuous where the contact begins or ends within the
// step. Newmark: f = c w dp/dt at t_n+1 while touching, dp/dt the
// integrator's rate, w = min(1, (p_n+1 - ps) / |p_n+1 - p_n|): the force
// ramps in over the last step's motion beyond the set, continuous where the
// contact begins or ends (w -> 1 as the step shrinks). Statics: none.
#include <cmath>

#include "core/StepRule.h"

namespace c2d {

struct DamperForce {
  double force = 0;  // along the penetration (pushing the bodies apart while it grows)
  double slope = 0;  // d force / d p_n+1
};

// The Newmark dashpot's ramp: the weight w = min(1, (p_n+1 - ps) / |p_n+1 -
// p_n|) of c dp/dt while touching (p_n+1 > ps; 0 otherwise) and dw/dp_n+1.
// Shared by the ground (damperForce) and the member pairs, whose rate is a
// vector's (core/contact/PairContact.cpp).
struct DamperRamp {
  double w = 0;
  double slope = 0;  // dw / dp_n+1
};
DamperRamp damperRamp(double ps, double p0, double p1);

// The coefficient (kN s/m) of the damping ratio zeta for stiffness k and mass
// m; none for a node that does not move (m infinite) or has no mass.
inline double damperCoefficient(double zeta, double k, double m) {
  return zeta > 0 && k > 0 && m > 0 && std::isfinite(m) ? 2 * zeta * std::sqrt(k * m) : 0.0;
}

// The dashpot's force over the step from p0 (t_n) to p1 (t_n+1) with the set
// ps; rate: dp/dt at t_n+1 under the Newmark rule (unused by the mid-point
// scheme), rateSlope its derivative with respect to p_n+1.
DamperForce damperForce(double c, double ps, double p0, double p1, double rate, double rateSlope,
                        const StepRule& rule);

// The energy the dashpot takes over the step under the mid-point scheme (>= 0);
// 0 otherwise (the Newmark rule's work is the integrator's).
double damperDissipation(double c, double ps, double p0, double p1, const StepRule& rule);

}  // namespace c2d
