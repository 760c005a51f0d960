#pragma once
// After TIME: a prescribed value (DISPlacement) that the proportional load
// took beyond the coordinates' limit, where the residual would be no number.
#include <string>

#include "core/Model.h"

namespace c2d {

class Analysis;

// Empty when every prescribed value is within the limit; else what the run
// fails with: the node and dof, the value reached, the DISPlacement value, the
// factor and its proportional load table.
std::string prescribedBeyondReach(const Model& model, Analysis& analysis);

}  // namespace c2d
