#pragma once
// One node-segment pair of the member contact (docs/design/member-contact.md
// describes the model: the penetration, the held sides, the friction along the
// segment and the discrete-gradient force): the pair's side and penetration,
// and its force law over a step.
#include <Eigen/Core>

#include "core/StepRule.h"
#include "core/Types.h"

namespace c2d {

using PairVec = Eigen::Matrix<double, 6, 1>;  // node x, segment ends a, b: (x, y) each
using PairMat = Eigen::Matrix<double, 6, 6>;

// Positions of the node and the segment ends at one instant.
struct PairPositions {
  Vec2 x, a, b;
};

// The side of the node relative to the line a->b: +1 left (or on it), -1 right.
int pairSide(const PairPositions& q);
// Penetration of the pair for the side s and contact distance h (see above);
// face > 0: the node is held on the side s (a ruptured joint's pair), also
// beyond the segment's ends, and meets the segment's end faces; face is the
// pair's full contact distance (its reach h may be offset to about 0), which
// scales the faces (docs/design/member-contact.md).
double pairPenetration(const PairPositions& q, int side, double h, double face = 0);

// The rate of the pair's penetration p for the velocities v of its points
// (dp/dt = grad p . dz/dt, z = (x - a, b - a)).
double pairPenetrationRate(const PairPositions& q, const PairPositions& v, int side, double h,
                           double face = 0);

using PairZ = Eigen::Matrix<double, 4, 1>;  // z = (x - a, b - a)

// The force law of a pair: penalty stiffness k, the dashpot's coefficient c
// (kN s/m, core/contact/ContactDamper.h), restitution e and the pair's loading point q
// at t_n (core/contact/CrushingLaw.h; e = 1: elastic, q unused); zv and za: dz/dt and
// d2z/dt2 at t_n, from which Newmark's rate at t_n+1 follows.
struct PairLaw {
  double k = 0, c = 0, restitution = 1, q = 0;
  double mu = 0, stretch = 0;  // friction coefficient, the friction spring's stretch at t_n
  double stick = 0;            // the friction's stick dashpot (kN s/m, SpringFriction.h)
  PairZ zv = PairZ::Zero(), za = PairZ::Zero();
};

// What a pair's step did: its penetrations at t_n and t_n+1, the friction
// spring's stretch at t_n+1 and the energy its sliding (or letting go) took.
struct PairOutcome {
  double p0 = 0, p1 = 0, stretch = 0, slipped = 0;
};

// The pair's contact force (added to the residual as an internal force: the
// gradient of the energy) and its derivative with respect to the positions at
// t_n+1, for the positions at t_n (q0) and t_n+1 (q1). False, with nothing
// written, when the pair carries no force.
bool pairContact(const PairPositions& q0, const PairPositions& q1, int side, double h,
                 const PairLaw& law, const StepRule& rule, bool wantTangent, PairVec& force,
                 PairMat& tangent, PairOutcome* outcome = nullptr, double face = 0);

// pairContact in two parts, so that a caller forms a pair's law only for a
// pair that touches (most candidates of an assembly are apart): the pair's
// relative positions and penetrations at t_n and t_n+1 (with the gradient at
// t_n+1, and its Hessian where the force law needs it), as pairContact finds
// them, and whether it touches over the step (carries a force).
struct PairStep {
  PairZ z0 = PairZ::Zero(), z1 = PairZ::Zero();
  double p0 = 0, p1 = 0;
  PairZ g1 = PairZ::Zero();
  Eigen::Matrix4d H1 = Eigen::Matrix4d::Zero();
};
bool pairTouches(const PairPositions& q0, const PairPositions& q1, int side, double h,
                 const StepRule& rule, bool wantTangent, PairStep& step, double face = 0);
// The same in two parts: what the positions at t_n give (z0, p0), which a
// step's iterations keep, and the rest from the positions at t_n+1.
void pairStart(const PairPositions& q0, int side, double h, PairStep& step, double face = 0);
bool pairTouches(const PairPositions& q1, int side, double h, const StepRule& rule,
                 bool wantTangent, PairStep& step, double face = 0);
// The force (and tangent) of a pair that touches, from its step; the same
// arguments as pairContact's.
void pairContact(const PairStep& step, int side, double h, const PairLaw& law, const StepRule& rule,
                 bool wantTangent, PairVec& force, PairMat& tangent, PairOutcome* outcome = nullptr,
                 double face = 0);

}  // namespace c2d
