#pragma once
// Topology changes during a run, made after a commit so that the state is
// continuous across them: a geometrically exact element whose softening hinge
// has fully softened gets its revolute joint (elements/HingeToJoint.h,
// jointFailedHinges), and a joint whose relative rotation exceeds its rupture
// rotation separates the pieces (elements/Joints.h, ruptureJoints). The
// analysis then rebuilds its dof map, pattern and factorization.
#include <functional>

#include "core/Model.h"
#include "core/State.h"

namespace c2d {

struct TopologyEvent {
  enum class Kind { JointFormed, JointRuptured };
  Kind kind = Kind::JointFormed;
  int element = -1;             // 0-based
  int master = -1, slave = -1;  // 0-based nodes
  double rotation = 0;          // the joint's relative rotation (rad)
  double limit = 0;             // rupture rotation (ruptures)
};

class TopologyEvents {
 public:
  // Called once per event, after the model changed.
  std::function<void(const TopologyEvent&)> onEvent;
  // True when the model changed.
  bool afterCommit(Model& model, State& state);
};

}  // namespace c2d
