#pragma once
// Members passing through each other: the pairs of elements whose centre lines
// cross at a state. Elements that share a node, or nodes tied by a joint, meet
// by construction and are not checked. A proper crossing only: segments that
// touch or overlap along a line are not reported, nor two whose crossing lies
// within 5 % of their contact distance (the sum of their section radii,
// sqrt(3 I / A) each) of an end of each: their tips overlap by millimetres,
// as two pieces of a ruptured joint pressed together by the penalty contact
// do (the node held on the other's centre line penetrates it by its force
// over k).
//
// The check is linear in the number of elements (core/contact/ContactGrid.h). A run
// calls it at its end and reports every crossing in its log: penalty contact
// too soft for the impact speed, or a step too long, lets a node tunnel through
// a member.
#include <vector>

#include "core/Model.h"
#include "core/State.h"

namespace c2d {

struct MemberCrossing {
  int first = -1, second = -1;  // element indices (0-based), first < second
  Vec2 point = Vec2::Zero();     // where the centre lines cross
  // For each member: its end node nearer to the crossing (0-based) and the
  // distance from that node to the crossing along the member.
  int nearNode[2] = {-1, -1};
  double fromNode[2] = {0.0, 0.0};
};

// Pairs ordered by (first, second), positions from the trial displacements s.u.
std::vector<MemberCrossing> findCrossings(const Model& model, const State& s);

}  // namespace c2d
