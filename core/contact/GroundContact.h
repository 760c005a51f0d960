#pragma once
// Frictionless penalty contact of every node with a rigid ground line y = y0
// (paper section 4, eqs 72-75). Penetration g = y0 - y >= 0 gives an upward
// force p = k g and the stored energy U = k <g>^2 / 2.
//
// Restitution e < 1: the contact crushes. The force follows k g while the
// penetration grows past its largest value q since the node touched down (the
// loading point, State::crush), and unloads and reloads below q with the
// stiffness k / e^2: f = <k q - (k / e^2)(q - g)>, zero below the set
// g_s = q (1 - e^2). A node striking the ground with speed v leaves it with
// e v whatever its mass, speed and k; the loading work k (g^2 - q^2)(1 - e^2)/2
// beyond q is dissipated, and U = f^2 e^2 / (2 k) is stored. A node off the
// ground (g <= 0) starts afresh (q = 0). For e = 1 this is the elastic law.
//
// With the mid-point scheme the force is the discrete gradient of U between t_n
// and t_n+1, so an impact conserves energy exactly (e = 1, zeta = 0). A node
// whose turn falls inside a step gets the peak its mass came back from as its
// loading point (core/contact/CrushingLaw.h crushingLoadingPoint), so that the crushing
// dissipates what the impact brought whatever the step.
//
// Damping (zeta > 0, core/contact/ContactDamper.h): a dashpot c dp/dt on the node's
// penetration beyond the set while it touches, c = 2 zeta sqrt(k m) with m the
// node's own mass (core/NodeMass.h): the same damper at every step.
//
// Friction (mu > 0, the law in core/contact/SpringFriction.h): Coulomb friction
// on every node with a normal force N > 0 (the penalty force without the
// dashpot, >= 0 on every branch). The node is held by a horizontal stick
// element anchored where it last slid (its stretch x - a: State::stretch): a
// spring of the ground's stiffness k with a dashpot 2 sqrt(k m) beside it (m
// the node's mass, critical damping); it slides when the element's force
// reaches mu N, the anchor then following it. A node at rest sticks to within
// mu N / k (mu times its penetration) and never creeps; a node striking the
// ground sideways meets mu N at once (the dashpot), so an impact takes
// Coulomb's impulse whatever its duration; sliding is resisted by the full
// mu N whatever the node's own mass. The spring stores
// k (x - a)^2 / 2 <= (mu N)^2 / (2 k). With the mid-point scheme N is the
// step's normal force and the friction force is the element's work along the
// straight path from x_n to x_n+1 divided by the step, so that its work is the
// spring energy's change plus what the dashpot and sliding dissipated.
// Otherwise the element's force at t_n+1.
#include "core/Model.h"
#include "core/StepRule.h"

namespace c2d {

struct ContactForce {
  double force = 0;          // upward force on the node (>= 0 unless the dashpot pulls)
  double tangent = 0;        // d(force)/d(penetration at t_n+1): the stiffness on the node's v dof
  double normal = 0;         // the penalty part of force (no dissipation): >= 0, friction's N
  double normalTangent = 0;  // d(normal)/d(penetration at t_n+1)
};

// Horizontal force on a node, its derivatives with respect to the node's
// position at t_n+1, and the anchor at t_n+1.
struct FrictionForce {
  double force = 0;   // f_t
  double dx = 0;      // d f_t / d x_n+1
  double dy = 0;      // d f_t / d y_n+1 (through N)
  double anchor = 0;  // where the spring is anchored at the end of the step
  double slipped = 0; // energy sliding dissipated over the step (>= 0)
};

// The dashpot of a node's contact: its coefficient c (kN s/m, zeta's for the
// node's mass: core/contact/ContactDamper.h) and the node's vertical velocity and
// acceleration at t_n (from which Newmark's rate at t_n+1 follows).
struct GroundDamper {
  double c = 0, vn = 0, an = 0;
};

// Penetration of a node at vertical position y.
inline double penetration(const Ground& g, double y) { return g.y0 - y; }
// Energy stored in the contact of a node at vertical position y whose loading
// point was q at the last commit.
double contactEnergy(const Ground& g, double q, double y);
// The loading point after a step that ends at y, of a node of mass m whose
// vertical velocity went from vn to v (core/contact/CrushingLaw.h crushingLoadingPoint).
double loadingPoint(const Ground& g, double q, double m, double y, double vn, double v);

// What a node's contact owes it at a commit: the mid-point scheme's velocity
// weight beta takes beta m (v_n+1 - v_n)^2 from a node of mass m in every
// step (solvers/TimeIntegrator.h), about (pi/2) beta omega h of an impact's
// energy per contact phase (omega the phase's frequency), which would come
// out of the restitution. The contact gives it back: while it loads, e^2 of
// each step's share is owed (what the crushing would have stored of it);
// while it unloads, the whole share, and what is owed is given back at once
// by lowering the loading point (crushingRaised: the set shrinks and the law
// pushes back harder). Once the contact reloads below its loading point
// before letting go it has settled (a resting node: its ringing is damped as
// the scheme damps it) and owes nothing until it loads past its loading
// point again or leaves the ground. With it a node leaves at e v under
// DYNAmic,ENERgy's decay too (ImpactRestitutionTest).
inline constexpr double kImpactSettled = -1;
struct ImpactOwed {
  double q = 0;      // the loading point after the commit
  double owed = 0;   // what stays owed (kImpactSettled once settled)
  double given = 0;  // the energy given back at the commit (>= 0)
};
// The node's loading point was q at t_n and is `loading` after the step
// (loadingPoint), its penetration p0 at t_n and p1 at t_n+1, its mass m and
// its vertical velocity from vn to v; owed: what it owed at t_n.
ImpactOwed groundImpactOwed(const Ground& g, double q, double loading, double owed, double p0,
                            double p1, double m, double vn, double v, const StepRule& rule);

// Force and its stiffness for the node's vertical position yn (t_n) and y (t_n+1)
// and its loading point q at t_n, under the step rule, with the node's dashpot
// d. Mid-point: the work of the crushing law on the straight path from yn to y
// divided by the step (a discrete gradient, so that the force's work is the
// stored energy's change plus what crushing dissipates); otherwise the law at
// t_n+1.
ContactForce groundContact(const Ground& g, double q, double yn, double y, const StepRule& rule,
                           const GroundDamper& d = {});

// Friction on a node whose normal force is c (groundContact at the same
// rule), anchored at a (t_n), moving horizontally from xn to x; stick: the
// stick element's dashpot (kN s/m, frictionStickDamping for the node's mass).
FrictionForce groundFriction(const Ground& g, const ContactForce& c, double a, double xn, double x,
                             const StepRule& rule, double stick = 0);
// Energy stored in a friction spring stretched by x - a.
inline double frictionEnergy(const Ground& g, double stretch) {
  return 0.5 * g.k * stretch * stretch;
}

// Energy the ground's contact law takes from a node over the step from (xn, yn)
// to (x, y), >= 0: the crushing beyond the loading point q, the dashpot
// (damper, as groundContact's) under the mid-point scheme and the friction's stick dashpot
// (coefficient stick) and sliding from the anchor a. Under the static and Newmark rules the penalty force is the plain
// gradient at t_n+1; what that integration loses or gains is the scheme's, not
// counted here.
double groundDissipation(const Ground& g, double q, double a, double xn, double yn, double x,
                         double y, const StepRule& rule, const GroundDamper& damper = {},
                         double stick = 0);

}  // namespace c2d
