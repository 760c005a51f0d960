#pragma once
// The joints of hinges that open at the element ends (HingeSite::Ends,
// materials/HingedBending): after the commit that made an opening permanent,
// the end's node gets a slave node of the same state, the element's end moves
// to it and a condensed joint there carries the hinge's softening law
// (materials/EndHinge, elements/JointedElement), with the capacity of the sign
// of the moment at opening and its failure jump at the axial force then. The
// state is continuous: the joint's relative rotation starts at zero. The
// element's section then marks the end as made (endHinge +-2), so that a joint
// that ruptures later is not made again.
#include <vector>

#include "core/Model.h"
#include "core/State.h"

namespace c2d {

struct OpenedHinge {
  int element = -1;             // 0-based
  int end = 0;                  // 0: node 1, 1: node 2
  int sign = 1;                 // of the moment at opening
  int master = -1, slave = -1;  // 0-based nodes
  double moment = 0;            // the end moment at opening
  double ultimate = 0;          // Mu at the axial force then
  double axialForce = 0;
  double failureJump = 0;       // xiF of the hinge
  double shearSpan = 0;         // L_V it follows (RC sections), 0: none
};

// True when any element has an opened end hinge without its joint.
bool endHingesDue(const Model& model);
// Makes the joints; bumps the topology version when it made any.
std::vector<OpenedHinge> openEndHinges(Model& model, State& state);
// The largest |M|/Mu(N) of the hinges that joints carry (0: none), and the
// element that carries it (-1: none).
double endHingeRatio(const Model& model, int* element = nullptr);

}  // namespace c2d
