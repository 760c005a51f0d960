#pragma once
// The boxes the nodes sweep over a step (their positions at t_n and t_n+1),
// found once per assembly: the member contact's first test of a candidate
// pair. A node's box inflated by the pair's reach that misses the box of the
// segment (its two nodes' boxes joined) is the same test MemberContact makes
// on the pair's positions (core/contact/MemberContact.h: positions), from a few
// contiguous boxes instead of nine scattered coordinates and displacements: of
// the 1840 candidates per assembly of the main example with member contact,
// 316 pass it and 121 carry a force.
#include <vector>

#include "core/contact/ContactGrid.h"
#include "core/contact/MemberContact.h"
#include "core/Model.h"
#include "core/State.h"

namespace c2d {

class SweptBoxes {
 public:
  // The boxes of every node at the state s (allocates only when nodes were added).
  void update(const Model& model, const State& s);

  // The pair's swept boxes are within its contact distance plus extra.
  bool reach(const ContactPair& pair, double extra) const {
    Box seg = box_[pair.a];
    const Box& b = box_[pair.b];
    seg.add(b.x0, b.y0);
    seg.add(b.x1, b.y1);
    return box_[pair.node].inflated(pair.h + extra).overlaps(seg);
  }

 private:
  std::vector<Box> box_;  // per node
};

}  // namespace c2d
