#pragma once
// The boxes the nodes sweep over a step (their positions at t_n and t_n+1),
// found once per assembly: the member contact's first test of a candidate
// pair. A node's box inflated by the pair's reach that misses the box of the
// segment (its two nodes' boxes joined) is the same test as that on the
// pair's positions (core/contact/PairMotion.h pairPositions), from a few
// contiguous boxes instead of nine scattered coordinates and displacements;
// most candidates fail it.
#include <Eigen/Core>
#include <vector>

#include "core/contact/ContactGrid.h"
#include "core/contact/ContactPair.h"
#include "core/Model.h"
#include "core/State.h"

namespace c2d {

class SweptBoxes {
 public:
  // The boxes of every node at the state s (allocates only when nodes were
  // added), and in the same pass how far the nodes have moved from the state
  // near() last found its list for.
  void update(const Model& model, const State& s);
  const Box& box(int node) const { return box_[node]; }

  // The candidates (indices, ascending) that may pass reach(pair, extra) at
  // s, after update(s): those within extra + slack at the state the list was found
  // for, kept while the candidates (their version) and the positions at t_n
  // are the same and no node's position at t_n+1 has moved by more than a
  // quarter of the slack from that state's (a box grows by at most that a
  // side, so a pair comes at most half the slack closer). A step's Newton
  // iterations move the nodes little: most assemblies test these few pairs
  // instead of every candidate.
  const std::vector<int>& near(const State& s, const std::vector<ContactPair>& candidates,
                               int version, double extra, double slack);
  // Counts the lists near() has found: a new value, a list found afresh at
  // the state of the call.
  int listVersion() const { return listVersion_; }
  // The most a node's coordinate moves from the state a list was found at
  // while near() keeps it.
  static double holds(double slack) { return 0.25 * slack; }

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
  // near() and what it was found for.
  std::vector<int> near_;
  Eigen::VectorXd nearU_, nearUn_;
  // update()'s: the positions at t_n are near()'s, and the largest move of a
  // position at t_n+1 from near()'s (a coordinate).
  bool sameStart_ = false;
  double moved_ = 0;
  int nearVersion_ = -1;
  int listVersion_ = 0;
  double nearExtra_ = -1, nearSlack_ = -1;
};

}  // namespace c2d
