#pragma once
// Setting up the revolute joints of a model (core/Model.h Joint) and reporting
// the state of their slave nodes.
//
// A JointForm::Condensed joint is realised by wrapping the element attached to
// the slave node in a JointedElement (the slave then disappears from the global
// system; its rotation is the master's plus the element's relative rotation).
// That needs exactly one element at the slave node and a slave node that is not
// itself loaded, restrained or the master of another joint: otherwise the joint
// is switched to JointForm::Shared, where the slave keeps its own rotation dof
// (with its restraint and loads) and the dof map gives its translations the
// master's equations (so a chain of joints, whose slave is the next one's
// master, stays in the global system). A Condensed joint whose slave has no
// element is left alone.
#include <vector>

#include "core/Model.h"
#include "core/State.h"
#include "elements/JointedElement.h"

namespace c2d {

// Wraps the elements at the slaves of Condensed joints (or switches those joints
// to Shared, as above). Idempotent: a second call changes nothing. Bumps the
// model's topology version when it changed anything. Returns the number of
// joints it wrapped or switched.
int installJoints(Model& model);
// A Condensed joint can be wrapped: exactly one element at its slave, which
// carries no nodal data and masters no other joint (else it becomes Shared).
bool condensable(const Model& model, const Joint& joint);
// The largest joint friction moment Mr (SOFTening's) of the elements at a node.
double jointFriction(const Model& model, int node);

// The element inside any joint wrappers (an element with joints at both ends
// is wrapped twice).
Element& innermost(Element& e);
const Element& innermost(const Element& e);
// The kinematics of e's innermost element at the state's displacements: each
// wrapper's relative rotation added at its end (JointedElement::innerKinematics).
ElementKinematics innermostKinematics(const Element& e, const State& state);

// The element chain `el` without its joint wrapper at `slave` (the slave
// becomes the node of that end).
std::unique_ptr<Element> withoutJoint(std::unique_ptr<Element> el, int slave);

// The jointed elements of the model, wrappers inside wrappers included
// (borrowed pointers, valid until the element list changes).
std::vector<JointedElement*> jointedElements(Model& model);
std::vector<const JointedElement*> jointedElements(const Model& model);
// Calls f(e, j) for every jointed element j of element e (Model or const
// Model), wrappers inside wrappers included, outermost first.
template <class ModelT, class F>
void forEachJointed(ModelT& model, F&& f) {
  for (int e = 0; e < model.numElements(); ++e)
    for (auto* j = model.hasElement(e) ? asJointed(&model.element(e)) : nullptr; j;
         j = asJointed(&j->inner()))
      f(e, j);
}

// Per node: the element ends at it, a joint's master and slave counting two
// (but for the joints k with gone[k] set: removed in the pass under way).
std::vector<int> nodeAttachments(const Model& model, const std::vector<char>& gone = {});
// A free end: a node that one element end holds and no joint, its rotation
// free and unloaded by a nodal moment (attachments: nodeAttachments' count).
// It carries no moment: no member breaks there, and no joint forms at it.
bool freeEnd(const Model& model, int node, int attachments);
// Whether a free end other than one at the node's own place (the pieces of a
// joint ruptured there: the members left may still break at it) lies within
// the distance lb of the node, in the reference configuration (the distance
// along the material). Next to a free end the moment grows as V x from zero,
// so a member that carries no more shear than Vu cannot break nearer than
// Mu/Vu (SOFTening's or the section's shortest piece Lb).
bool nearFreeEnd(const Model& model, const std::vector<int>& attached, int node, double lb);
// The free ends (attached: nodeAttachments), and the nearest of them to the
// node within lb but not at its place (-1: none).
std::vector<int> freeEnds(const Model& model, const std::vector<int>& attached);
int freeEndWithin(const Model& model, const std::vector<int>& ends, int node, double lb);

// A joint past its rupture rotation that stays: within its material's
// shortest piece Lb of the free end freeEnd (0-based node).
struct HeldJoint {
  int master = -1, slave = -1, element = -1, freeEnd = -1;
  double rotation = 0, limit = 0, pieceLength = 0;
};

// A joint that ruptured: the two pieces separated at the slave node.
struct RupturedJoint {
  int master = -1, slave = -1;  // 0-based nodes
  int element = -1;             // 0-based index of the element at the slave
  double rotation = 0;          // relative rotation at rupture (rad)
  double limit = 0;             // the rupture rotation thetaR of that element's material
};

// After a commit: every joint whose relative rotation exceeds in magnitude the
// rupture rotation thetaR of the material of the element at its slave
// (SOFTening LINEar Mu Ks thetaR) ruptures: the joint is removed, and the slave
// node, at the master's position with the slave rotation and their rates,
// becomes a node of its own, so the pieces separate in translation too. The
// state is continuous (nothing moves, no velocity changes). A joint whose
// master node penetrates the ground waits until the node leaves it (the new
// node would bring a penalty force and energy of its own). A joint whose master
// lies within its material's shortest piece Lb of a free end (nearFreeEnd: a
// piece that a rupture nearby set free, the member's own end) does not
// rupture: it turns on with its friction, so that no piece shorter than Lb
// breaks off whatever the mesh (joints ruptured in this pass count). Bumps the
// topology version when anything ruptured.
// held (optional) receives the joints past thetaR that stay so.
std::vector<RupturedJoint> ruptureJoints(Model& model, State& state,
                                         std::vector<HeldJoint>* held = nullptr);

// After elements were removed from the model (BLASt, REMOve): every joint left
// with a side that no element holds any more is dissolved (a condensed joint
// whose element is gone, or whose master no other element holds: the element
// takes the slave node as its own, with its state, as at a rupture; a shared
// joint with a side without elements). State continuous. Bumps the topology
// version when it dissolved any; returns the joints dissolved.
std::vector<Joint> dissolveLooseJoints(Model& model, State& state);

// Writes the state of the slave nodes of Condensed joints into the state
// vectors, for output: translations, velocities and accelerations are the
// master's, the rotation (and its rates) the master's plus the relative ones;
// trial values from the elements' trial state, committed from their committed
// state. Call after a commit. Resizes the state when the model has more nodes.
void syncSlaveNodes(const Model& model, State& state);

}  // namespace c2d
