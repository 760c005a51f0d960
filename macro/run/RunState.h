#pragma once
// The run's own part of a restart file (SAVE, REST; solvers/RestartFile.h keeps
// it beside the model's and the analysis'): the watches' state (hinge steps,
// counters, peaks, the energy balance) and the step control's (cutting, dtmin,
// the nominal dt, the cuts), interleaved in the file's fixed order.
#include <string>

#include "core/Model.h"
#include "macro/run/RunWatches.h"
#include "macro/run/StepControl.h"

namespace c2d {

std::string runStateBytes(const RunWatches& watches, const StepControl& stepControl);

// Throws CheckpointError when the bytes do not fit `model` (the hinge steps
// against its element count, the deepest node against its nodes) or end early.
void readRunState(const std::string& bytes, const Model& model, RunWatches& watches,
                  StepControl& stepControl);

}  // namespace c2d
