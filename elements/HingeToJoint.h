#pragma once
// HINGE2JOINT: the switch from the failure phase to the collapse phase (paper
// section 3, Fig. 5). Every activated softening hinge becomes a revolute joint,
// and every element becomes a geometrically exact elastic Reissner beam that
// starts with the section forces the old element had, so that the switch itself
// releases nothing but the hinge moments.
//
// For each element whose hinge is active (core/Hinge.h):
//  - the joint goes to the element end nearer the hinge's critical section:
//    end 1 for position < 0.5, end 2 for position > 0.5; at position 0.5 (the
//    one-point element) the end whose internal end moment (the rotation
//    component of the element's residual f_int at the current state) is larger
//    in magnitude, i.e. the end nearer the larger bending moment; a tie (equal
//    within 1e-12 relative, a uniform moment) goes to end 1;
//  - a slave node is added at the master's coordinates (free: no restraint, no
//    load), the element's end is moved to it, and a Condensed joint is added;
//  - the rotation jump alpha becomes the joint's relative rotation. In eq (20),
//    psi(s) = N1 psi1 + N2 psi2 + (H_Gamma - N2) alpha: the rotation just past
//    the hinge exceeds the one just before it by alpha. Moving the jump to end 1
//    the element starts at psi1 + alpha, so psi_r = psi_s - psi_m = +alpha; moving
//    it to end 2 the element ends at psi2 - alpha, so psi_r = -alpha. Either way
//    the element's curvature (psi2 - psi1 - alpha)/l is the one it had.
// Then every element that is not yet a ReissnerFrame is rebuilt as one, from a
// copy of its material set with kinematics = Finite and the hardening and
// softening data dropped (the collapse phase has elastic members; the model's
// material sets are not changed), with the initial strain
//   E0 = E(d) - C^-1 (N, V, M)_old
// so that its section forces at the current displacements d (the slave end
// rotated by psi_m + psi_r) equal the old element's. Elements at the slaves of
// Condensed joints are wrapped by installJoints() (elements/Joints.h); existing
// jointed elements are rebuilt inside their wrapper and keep their relative
// rotation and its rates.
//
// The state: resized to the new node count, slave nodes written by
// syncSlaveNodes() (master translations and rates; rotation master + psi_r,
// relative rates zero), and committed = trial. The new elements are evaluated
// and committed at that state with the relative rotations as set, so their
// section forces and energies are reported from the start; the first step then
// solves the joints' moment equations. Commit the converged failure-phase step
// (Analysis::commit) before the call, so that the next step does not re-commit
// the old one with the new elements.
#include <vector>

#include "core/Model.h"
#include "core/State.h"

namespace c2d {

struct CreatedJoint {
  int element = -1;             // 0-based element index
  int master = -1, slave = -1;  // 0-based node indices (slave: the new node)
  int slaveEnd = 0;             // 0: element node 1, 1: element node 2
  double position = 0.5;        // hinge position s_d / l_e
  double jump = 0;              // rotation jump alpha of the hinge
  double relativeRotation = 0;  // psi_r at the start: +alpha (end 1) or -alpha (end 2)
};

// Bumps the topology version when it rebuilt anything (a model already in the
// collapse phase is left unchanged). Throws AnalysisError when an element's material set is missing
// or an element cannot be evaluated at the current state.
std::vector<CreatedJoint> hingeToJoint(Model& model, State& state);

}  // namespace c2d
