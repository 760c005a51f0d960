#pragma once
// A contact's motion over a step, as the step control through impacts sees it
// (solvers/ImpactSteps.h): a ground node's or a member pair's penetration p at
// t_n and t_n+1 and its rate dp/dt there (the integrator's velocities), its
// law (stiffness k, restitution e, loading point q at t_n, dashpot c: the
// core/contact/CrushingLaw.h and core/contact/ContactDamper.h of its record) and the mass it
// moves (core/NodeMass.h, core/contact/PairMotion.h).
namespace c2d {

struct ContactMotion {
  double p0 = 0, p1 = 0;  // penetration at t_n and t_n+1
  double r0 = 0, r1 = 0;  // dp/dt at t_n and t_n+1
  double k = 0, e = 1, q = 0, c = 0;
  double m = 0;  // t; infinite for a contact that does not move
  // The energy of that mass resting on the contact under gravity,
  // (m g)^2 / (2 k): the scale of a resting body's chatter (0 without gravity).
  double rest = 0;
};

}  // namespace c2d
