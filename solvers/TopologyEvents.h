#pragma once
// Topology changes during a run, made after a commit so that the state is
// continuous across them: a hinge opened at an element end gets the joint that
// carries it (elements/EndHinges.h), a member whose bars fractured or that
// failed in shear is separated from one of its ends (elements/BarFractures.h), a geometrically exact element
// whose softening hinge has fully softened gets its revolute joint
// (elements/HingeToJoint.h, jointFailedHinges), and a joint whose relative
// rotation exceeds its rupture rotation separates the pieces
// (elements/Joints.h, ruptureJoints). The analysis then rebuilds its dof map,
// pattern and factorization.
#include <functional>
#include <vector>

#include "core/Hinge.h"
#include "core/Model.h"
#include "core/State.h"

namespace c2d {

class JointedElement;

struct TopologyEvent {
  // JointHeld: a joint past its rupture rotation within its material's
  // shortest piece of a free end (end: that node), reported once; the model
  // does not change.
  enum class Kind { JointFormed, JointRuptured, HingeOpened, BarsFractured, Sheared, JointHeld };
  Kind kind = Kind::JointFormed;
  int element = -1;             // 0-based
  int master = -1, slave = -1;  // 0-based nodes
  double rotation = 0;          // the joint's relative rotation (rad)
  double limit = 0;             // rupture rotation (ruptures, held joints)
  double pieceLength = 0;       // the shortest piece Lb (held joints)
  // HingeOpened: end (0, 1), the end moment, Mu and N at opening, failure jump;
  // BarsFractured, Sheared: end, the axial force, whether through a joint;
  // Sheared: the shear |V| and the capacity Vu(N) (as moment and ultimate).
  int end = 0;
  double moment = 0, ultimate = 0, axialForce = 0, failureJump = 0;
  double shearSpan = 0;  // HingeOpened: the L_V its failure jump follows (0: none)
  bool throughJoint = false;
};

class TopologyEvents {
 public:
  // Called once per event, after the model changed.
  std::function<void(const TopologyEvent&)> onEvent;
  // True when the model changed.
  bool afterCommit(Model& model, State& state);
  // The hinge carriers (innermost elements) and the joint wrappers of the
  // model's current topology, found once per topology version: most commits
  // have no failed hinge and no joint past a rupture rotation, and then cost
  // no search over the elements (a few dynamic casts per element, 4 % of the
  // ten-storey demolition decks at every commit). The analysis indexes when
  // the topology changes, so that the steps after it allocate nothing.
  void index(const Model& model);

 private:
  bool anyFailedHinge() const;
  bool anyEndHingeOrFracture() const;
  bool anyJointPastRupture(const Model& model, const State& state) const;

  const Model* indexedModel_ = nullptr;
  int indexedVersion_ = -1;
  std::vector<const HingeCarrier*> carriers_;  // every element's with a hinge law
  // Of those, the elements whose failed hinge becomes a joint (jointsWhenFailed).
  std::vector<const HingeCarrier*> jointCarriers_;
  std::vector<const JointedElement*> wrappers_;
  std::vector<int> heldReported_;  // slave nodes of the held joints reported
};

}  // namespace c2d
