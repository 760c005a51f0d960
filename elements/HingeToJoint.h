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
//    within 1e-12 relative, a uniform moment) goes to end 1; never to a free
//    end (elements/Joints.h freeEnd: no other member or joint there, which
//    carries no moment) or an end that already has a joint: the other end
//    then, and with neither no joint (the element keeps its hinge; a failed
//    one carries no moment);
//  - a slave node is added at the master's coordinates (free: no restraint, no
//    load), the element's end is moved to it, and a Condensed joint is added;
//  - the rotation jump alpha becomes the joint's relative rotation. In eq (20),
//    psi(s) = N1 psi1 + N2 psi2 + (H_Gamma - N2) alpha: the rotation just past
//    the hinge exceeds the one just before it by alpha. Moving the jump to end 1
//    the element starts at psi1 + alpha, so psi_r = psi_s - psi_m = +alpha; moving
//    it to end 2 the element ends at psi2 - alpha, so psi_r = -alpha. Either way
//    the element's curvature (psi2 - psi1 - alpha)/l is the one it had.
// Then every element that is not yet a ReissnerFrame (with MemberLaws::Elastic:
// not yet an elastic one) is rebuilt as one, from a copy of its material set
// with kinematics = Finite and, for MemberLaws::Elastic, the hardening and
// softening data dropped (the model's material sets are not changed), with the
// initial strain
//   E0 = E(d) - C^-1 (N, V, M)_old    (inelastic bending: E0_3 = K(d) - kp - M/EI)
// so that its section forces at the current displacements d (the slave end
// rotated by psi_m + psi_r) equal the old element's. An element that gets a
// joint at one end and already has one there gets it at its other end. Elements at the slaves of
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

// What becomes of the members.
enum class MemberLaws {
  Elastic,    // HINGE2JOINT: elastic Reissner beams from now on (the paper)
  Inelastic,  // HINGE2JOINT,INELastic: Reissner beams that keep their hardening and
              // softening laws and history (bulk plastic curvature); every element can
              // open a hinge (an element whose hinge became a joint: a new one)
};

// Bumps the topology version when it rebuilt anything (a model already in the
// collapse phase is left unchanged). Throws AnalysisError when an element's material set is missing
// or an element cannot be evaluated at the current state.
std::vector<CreatedJoint> hingeToJoint(Model& model, State& state,
                                       MemberLaws laws = MemberLaws::Elastic);

// During a run, after a commit: every geometrically exact element whose hinge
// has fully softened (moment zero) gets its revolute joint, as above with
// MemberLaws::Inelastic but for those elements only, so that the pieces can
// fold freely. The state is continuous: positions and velocities of every node
// are kept, the new joint starts with the jump as its relative rotation and zero
// relative rates, and the element's section forces are unchanged; joints the
// element already has keep their committed relative rotations and rates. An
// element with a joint at one end gets the new one at its other end (a link
// pinned at both ends); one with joints at both ends, or whose other end is
// free, gets none: its failed hinge stays failed (no moment, never back at Mu). No
// joint forms at a node within the material's shortest piece Lb (SOFTening's) of
// an intact joint's node or of a free end (a ruptured joint's pieces): an end
// there does not break either. (Small
// displacement elements keep their free embedded hinge: the failure phase of
// the paper.) Returns the joints made.
std::vector<CreatedJoint> jointFailedHinges(Model& model, State& state);
// Whether a failed hinge of element e becomes a joint there: e is geometrically
// exact and has an end that is neither a free end, jointed already, nor within
// its material's Lb of an intact joint or a free end (attached: nodeAttachments(model),
// elements/Joints.h).
bool jointsWhenFailed(const Model& model, const std::vector<int>& attached, const Element& e);

}  // namespace c2d
