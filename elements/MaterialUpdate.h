#pragma once
// MATErial given again during an analysis (MESH re-entry): the new data of a
// material set applied to the existing elements of that set through their
// MaterialChange ability (core/MaterialChange.h). Each element keeps its
// section forces at the committed state and its history; the new data act from
// the next evaluation on.
#include <string>
#include <vector>

#include "core/Error.h"
#include "core/MaterialSet.h"
#include "core/Model.h"
#include "core/State.h"

namespace c2d {

// Applies mat to every element whose material number is mat.number, except the
// elements in skip (0-based; e.g. the ones just built from the new set). Each
// element gets its committed displacements from state.un (nodes beyond the
// state's size: zero, a model not yet analysed). Commit the analysis first.
// Returns the first refusal as "element N: why"; the elements before it have
// taken the new data (the run is meant to end there). Bumps the topology version
// when any element changed, so that the assembler re-reads the masses and
// self-weight loads and the solver its hinge data.
Status changeMaterial(Model& model, const State& state, const MaterialSet& mat,
                      const std::vector<int>& skip = {});

}  // namespace c2d
