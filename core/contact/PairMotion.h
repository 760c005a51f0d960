#pragma once
// A member contact pair's motion (docs/design/member-contact.md): its
// positions over a step, the values of node vectors at its three points and
// the mass it moves, the reduced mass of the node and the segment's point,
//   1/m = 1/m_x + (1 - xi)^2 / m_a + xi^2 / m_b,
// xi the node's projection on the segment a-b clamped to [0, 1] and m_x, m_a,
// m_b the nodes' masses (core/NodeMass.h): a force at the segment's point moves
// its ends in proportion to their weights (1 - xi, xi). 0 when a node has no
// mass.
#include <Eigen/Core>
#include <vector>

#include "core/contact/ContactGrid.h"
#include "core/contact/ContactPair.h"
#include "core/contact/PairContact.h"
#include "core/Model.h"
#include "core/State.h"

namespace c2d {

// The pair's positions at t_n and t_n+1, and whether its swept boxes are
// within contact distance (plus extra). Inline: evaluated for every candidate
// at every assembly (core/contact/SweptBoxes.cpp forms the same boxes).
inline bool pairPositions(const ContactPair& pair, const Model& model, const State& s,
                          PairPositions& q0, PairPositions& q1, double extra = 0) {
  q0 = {nodePosition(model, s.un, pair.node), nodePosition(model, s.un, pair.a),
        nodePosition(model, s.un, pair.b)};
  q1 = {nodePosition(model, s.u, pair.node), nodePosition(model, s.u, pair.a),
        nodePosition(model, s.u, pair.b)};
  Box node = Box::point(q0.x.x(), q0.x.y()), seg = Box::point(q0.a.x(), q0.a.y());
  node.add(q1.x.x(), q1.x.y());
  seg.add(q0.b.x(), q0.b.y());
  seg.add(q1.a.x(), q1.a.y());
  seg.add(q1.b.x(), q1.b.y());
  return node.inflated(pair.h + extra).overlaps(seg);
}

// The translations of a node-dof vector (displacements, velocities,
// accelerations) at the pair's node and segment ends.
PairPositions pairValues(const Eigen::VectorXd& nodal, const ContactPair& pair);
// z = (x - a, b - a) of the three points' values.
inline PairZ pairZ(const PairPositions& p) {
  PairZ z;
  z << p.x - p.a, p.b - p.a;
  return z;
}
// The mass the pair moves at the positions q.
double pairMass(const std::vector<double>& masses, const ContactPair& pair, const PairPositions& q);

// The pair's loading point after the step from q0 to q1 (velocities s.vn and
// s.v) that ends at the penetration p1, seen from `side` at the contact
// distance h: core/contact/CrushingLaw.h crushingLoadingPoint for the pair's mass and
// the rates of its penetration, from the loading point q at t_n.
double pairLoadingPoint(const MemberContactData& data, const std::vector<double>& masses,
                        const ContactPair& pair, const State& s, const PairPositions& q0,
                        const PairPositions& q1, int side, double h, double face, double q,
                        double p1);

}  // namespace c2d
