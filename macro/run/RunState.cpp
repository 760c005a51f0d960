#include "macro/run/RunState.h"

#include <sstream>

#include "solvers/RestartFile.h"

namespace c2d {

// The order of the file's fields (format of solvers/RestartFile.h): the
// watches' and the step control's interleaved.
std::string runStateBytes(const RunWatches& watches, const StepControl& stepControl) {
  using namespace checkpoint;
  std::ostringstream out(std::ios::binary);
  const RunWatches::Saved w = watches.saved();
  const StepControl::Saved steps = stepControl.saved();
  putCount(out, w.hingeStep.size());
  for (int s : w.hingeStep) put(out, s);
  put(out, w.hingeCount);
  putBool(out, steps.cutting);
  for (double x : {steps.dtMin, steps.dtNominal, w.maxMomentRatio, w.peakGroundForce,
                   w.peakGroundTime, w.peakKinetic, w.restRatio, w.lastMoving, w.deepest.depth,
                   w.deepestTime})
    put(out, x);
  for (int x : {steps.stepsSinceCut, steps.cuts, w.jointsFormed, w.jointsRuptured, w.removed,
                w.deepest.node, w.hinges, w.fractures, w.shears})
    put(out, x);
  watches.saveEnergy(out);
  putBool(out, w.dynamicSeen);
  return out.str();
}

void readRunState(const std::string& bytes, const Model& model, RunWatches& watches,
                  StepControl& stepControl) {
  using namespace checkpoint;
  std::istringstream in(bytes, std::ios::binary);
  RunWatches::Saved w;
  StepControl::Saved steps;
  w.hingeStep.resize(getCount(in));
  for (int& s : w.hingeStep) s = get<int>(in);
  if (static_cast<int>(w.hingeStep.size()) != model.numElements())
    throw CheckpointError("hinge steps do not match the element count");
  w.hingeCount = get<int>(in);
  steps.cutting = getBool(in);
  for (double* x : {&steps.dtMin, &steps.dtNominal, &w.maxMomentRatio, &w.peakGroundForce,
                    &w.peakGroundTime, &w.peakKinetic, &w.restRatio, &w.lastMoving,
                    &w.deepest.depth, &w.deepestTime})
    *x = get<double>(in);
  for (int* x : {&steps.stepsSinceCut, &steps.cuts, &w.jointsFormed, &w.jointsRuptured,
                 &w.removed, &w.deepest.node, &w.hinges, &w.fractures, &w.shears})
    *x = get<int>(in);
  if (w.deepest.node >= model.numNodes())
    throw CheckpointError("the deepest node is not in the model");
  watches.loadEnergy(in);
  w.dynamicSeen = getBool(in);
  stepControl.restore(steps);
  watches.restore(w);
}

}  // namespace c2d
