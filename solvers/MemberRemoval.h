#pragma once
// Members removed during a run: the blasts of a demolition (BLASt, at given
// times) and REMOve (at once), the GSA alternate-path column removal.
//
// A removal is made after a commit, so the state is continuous across it. The
// removed elements leave the model (their slots stay empty: element numbers
// never change): their stiffness, mass, self-weight, floor loads and contact
// go with them, joints left with a side that nothing holds are dissolved
// (elements/Joints.h dissolveLooseJoints), and a node that no element holds any
// more leaves the model (no equations, no contact, not drawn, not debris).
//
// Release over td > 0 (GSA 2016: at most a tenth of the structure's first
// vertical period): the internal forces the element exerted on its nodes at
// the removal (a static evaluation at the committed displacements), with the
// constant loads it carried (weight, QLOAd), become a load on the rest that falls linearly to zero over td
// (core/Model.h ReleasedForce). td = 0: the element and its forces vanish at once.
//
// Timing: steps end exactly on every blast time and on every end of a release
// (the analysis splits a step there: its length stays that of DT), so a blast
// happens at its time and the released forces are integrated exactly.
//
// Energy: the kinetic, strain and contact energy that leaves with the removed
// elements and nodes is booked in the account's dissipated energy (it leaves
// the model), so the balance stays closed; the work of the released forces is
// external work.
#include <functional>
#include <string>
#include <vector>

#include "core/Error.h"

namespace c2d {

class Analysis;

struct RemovalEvent {
  double time = 0;
  std::vector<int> elements;     // 0-based, removed now
  // A blast's elements that had left the model before it (REMOve; two BLASt
  // records of one element are a deck error): a blast of none of its elements
  // removes nothing.
  std::vector<int> goneBefore;
  double release = 0;            // td: the release time of their forces
  std::vector<int> nodesLeaving;  // 0-based nodes that no element holds any more
  int jointsDissolved = 0;
  double energy = 0;  // kinetic + strain + contact energy that left with them
  bool scheduled = false;  // a BLASt record (else REMOve)
  SourceLoc origin;        // a blast's record (Blast::origin; empty: unknown)
  int blast = -1;          // a blast's index in Model::blasts() (-1: REMOve)
};

class MemberRemoval {
 public:
  explicit MemberRemoval(Analysis& analysis) : an_(analysis) {}

  // Called once per removal, after the model changed.
  std::function<void(const RemovalEvent&)> onEvent;

  // The earliest time after `t` (by more than the time tolerance) at which a
  // step must end: a blast not yet made or the end of a release; +infinity if none.
  double nextLanding(double t) const;
  // The time tolerance of a step of length dt.
  static double tolerance(double dt);

  // After a commit: the blasts due at the committed time are made, and the
  // released forces that ended are dropped; `changed` tells whether the model
  // changed. Fails when a blast would leave no element in the model.
  Status afterCommit(bool& changed);
  // REMOve: removes these elements (0-based) now, releasing their forces over
  // `release`. The state must be committed. Fails for an element not in the
  // model, and when no element would be left.
  Status removeNow(const std::vector<int>& elements, double release);

 private:
  // A removal of these elements that would leave the model without any:
  // the failure to report (what is asked, with the element count); empty if not.
  std::string leavesNothing(const std::vector<int>& elements) const;
  // Removes the elements at the committed time; returns what happened.
  RemovalEvent remove(const std::vector<int>& elements, double release, bool scheduled);

  Analysis& an_;
};

}  // namespace c2d
