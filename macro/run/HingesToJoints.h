#pragma once
// HINGe2joint in a BATCh block: every hinge of the model becomes a joint
// (elements/HingeToJoint.h) at the analysis's committed state, the analysis
// takes the new topology, and the log lists the joints made.
#include <ostream>
#include <vector>

#include "core/Model.h"
#include "elements/HingeToJoint.h"
#include "solvers/Analysis.h"

namespace c2d {

// After the commit that ends the step before it; laws: what the members
// become. Returns the joints made.
std::vector<CreatedJoint> turnHingesToJoints(Model& model, Analysis& analysis, MemberLaws laws,
                                             std::ostream& log);

}  // namespace c2d
