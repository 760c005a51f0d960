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

// The jointed elements of the model (borrowed pointers, valid until the
// element list changes).
std::vector<JointedElement*> jointedElements(Model& model);
std::vector<const JointedElement*> jointedElements(const Model& model);

// Writes the state of the slave nodes of Condensed joints into the state
// vectors, for output: translations, velocities and accelerations are the
// master's, the rotation (and its rates) the master's plus the relative ones;
// trial values from the elements' trial state, committed from their committed
// state. Call after a commit. Resizes the state when the model has more nodes.
void syncSlaveNodes(const Model& model, State& state);

}  // namespace c2d
