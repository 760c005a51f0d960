#pragma once
// Members with a hinge law (hardening or softening: RC members with strength)
// bent through more than a quarter turn between their two ends. No RC member
// gets there whole: its hinge ruptures at thetaR first. It is left when an
// element that carries a joint at one end loses its embedded hinge too (a
// second joint would leave it without rotational stiffness, so the failed
// hinge stays inside with M = 0): nothing then resists theta_b - theta_a, and
// the member folds with only its nodes' rotary inertia in the way. The run
// reports such members (a physically impossible state is never silent).
#include <vector>

#include "core/Model.h"
#include "core/State.h"

namespace c2d {

struct MemberFold {
  int element = -1;
  int nodes[2] = {-1, -1};  // the inner element's nodes (a joint's slave included)
  double fold = 0;          // |theta_b - theta_a| (rad)
  // The member carries a failed hinge (fully softened, M = 0) that made no
  // joint: the member had a joint at an end already, or the hinge lies
  // within SOFTening's shortest piece Lb of a joint or a free end
  // (elements/HingeToJoint.h). Nothing resists its turn.
  bool failedHinge = false;
};

// The folded members of the model at state.u, most folded first.
std::vector<MemberFold> foldedMembers(const Model& model, const State& state);

}  // namespace c2d
