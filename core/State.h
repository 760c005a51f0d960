#pragma once
// The analysis state: nodal values for every node dof (index node*3 + dof),
// trial (t_{n+1}) and committed (t_n). Stored per node dof rather than per
// equation so that it survives a renumbering when the topology changes.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "core/Element.h"

namespace c2d {

// What a member contact pair (node against element segment) keeps between
// steps (core/contact/MemberContact.h): its loading point q (the largest penetration
// since the contact began, for the crushing law), the stretch of its friction
// spring, the contact distance it met at (a topology change that changes the
// radii of its node or member does not change a contact under way) and its
// offset o, the penetration the pair had when it first met (two members set
// free inside each other's contact distance, at a joint that ruptured, start
// at zero force; o shrinks as they separate).
struct PairMemory {
  std::uint64_t key = 0;  // ContactPair::key()
  double q = 0, offset = 0;
  double stretch = 0;  // the friction spring's stretch along the segment
  double h = 0;        // the contact distance it met at (kept while in memory)
  // The side of the segment the node is held on while it has not cleared the
  // centre line (+1 left, -1 right; 0: the side it was on at t_n).
  int side = 0;
  bool operator==(const PairMemory&) const = default;
};

struct State {
  Eigen::VectorXd u, v, a;     // trial: total displacement, velocity, acceleration
  Eigen::VectorXd un, vn, an;  // committed
  double t = 0, tn = 0;        // time (pseudo-time in statics)
  double dt = 0;
  double prop = 0, propn = 0;  // proportional load factor at t and t_n
  double arcLambda = 0;        // extra load factor driven by arc-length (multiplies FORCe)
  double arcLambdan = 0;
  int step = 0;                // number of committed steps
  // Per node: the ground contact's loading point, the largest penetration
  // since the node last touched down (0 off the ground; core/contact/GroundContact.h).
  // Committed only: it changes when a step is committed.
  Eigen::VectorXd crush;
  // Per node: what the mid-point scheme's velocity decay took from the node's
  // ground impact under way and its contact has still to give back, or
  // kImpactSettled once the contact reloaded before letting go (0 off the
  // ground; core/contact/GroundContact.h groundImpactOwed). Committed only.
  Eigen::VectorXd owed;
  // Per node: the stretch x - a of its ground friction spring, a where it is
  // anchored (core/contact/GroundContact.h; 0 off the ground). Committed only.
  Eigen::VectorXd stretch;
  // The member contact pairs in contact at t_n (or with an offset), sorted by
  // key. Committed only.
  std::vector<PairMemory> pairs;

  void resize(int numNodes);   // keeps existing values, zero-fills new nodes
  // The values of an element with these nodes, in element dof order.
  ElementKinematics kinematics(const std::array<int, 2>& nodes) const;
  // The trial velocities of an element with these nodes, in element dof order.
  ElemVec velocities(const std::array<int, 2>& nodes) const;
  void commit();               // trial -> committed
  void revert();               // committed -> trial
};

}  // namespace c2d
