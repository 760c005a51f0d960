#pragma once
// Members whose bars fracture (RC sections, materials/AxialCapacity: the axial
// strain reached the fracture strain eu, located as a hinge event) or that
// fail in shear (|V| reached Vu(N), materials/ShearResistance, located the
// same way): after the commit that made the failure permanent, the member is
// separated from one of its ends, as a joint past its rupture rotation
// separates its pieces. At an
// end where it has a joint (a hinge, the broken section) the joint is removed
// and its slave node becomes the member's own; else the end's node gets a new
// node of the same state for the member. The state is continuous (nothing
// moves, no velocity changes); the member's force is released from then on.
// A member whose node at that end presses on the ground waits until it leaves
// (as elements/Joints.h ruptureJoints does).
#include <vector>

#include "core/Model.h"
#include "core/State.h"

namespace c2d {

struct FracturedMember {
  int element = -1;       // 0-based
  int end = 0;            // the end it left
  int node = -1;          // the node it left (0-based)
  int newNode = -1;       // its own node there now
  double axialForce = 0;  // the force its bars carried
  bool joint = false;     // it left through the joint at that end
  bool shear = false;     // a shear failure (else its bars fractured)
  double shearForce = 0, shearCapacity = 0;  // |V| and Vu(N) at the failure
};

bool fracturesDue(const Model& model);
// Bumps the topology version when it separated any.
std::vector<FracturedMember> separateFractured(Model& model, State& state);

}  // namespace c2d
