// ProblemRun's restart files (SAVE, REST): the run's own state beside the
// model's and the analysis', written and read back.
#include <sstream>

#include "elements/Joints.h"
#include "macro/run/ProblemRun.h"
#include "solvers/RestartFile.h"

namespace c2d {

// ------------------------------------------------------------------ restart

std::filesystem::path ProblemRun::restartPath(const Macro& m) const {
  std::string name = m.optionText.empty() ? options_.stem : m.optionText;
  if (std::filesystem::path(name).extension() != ".rst") name += ".rst";
  return options_.outDir / name;
}

// The order of the file's fields (format of solvers/RestartFile.h): the
// watches' and the step control's interleaved.
std::string ProblemRun::runState() const {
  using namespace checkpoint;
  std::ostringstream out(std::ios::binary);
  const RunWatches::Saved w = watches_.saved();
  const StepControl::Saved steps = steps_.saved();
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
  watches_.saveEnergy(out);
  putBool(out, w.dynamicSeen);
  return out.str();
}

void ProblemRun::setRunState(const std::string& bytes) {
  using namespace checkpoint;
  std::istringstream in(bytes, std::ios::binary);
  RunWatches::Saved w;
  StepControl::Saved steps;
  w.hingeStep.resize(getCount(in));
  for (int& s : w.hingeStep) s = get<int>(in);
  if (static_cast<int>(w.hingeStep.size()) != model_.numElements())
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
  if (w.deepest.node >= model_.numNodes())
    throw CheckpointError("the deepest node is not in the model");
  watches_.loadEnergy(in);
  w.dynamicSeen = getBool(in);
  steps_.restore(steps);
  watches_.restore(w);
}

void ProblemRun::saveRestart(const Macro& m) {
  const Status st = analysis_->commit();
  if (!st) fail(m, st.why);
  const std::filesystem::path file = restartPath(m);
  try {
    c2d::saveRestart(file, model_, *analysis_, runState(), input_);
  } catch (const IoError&) {
    throw;
  } catch (const std::exception& e) {
    fail(m, e.what());
  }
  // The linear solver starts afresh here, as it does in a run restarted from this
  // file (a new analysis: CHOLMOD first again, KLU's pivot order chosen anew), so
  // that the two runs stay identical to the last bit.
  analysis_->setLinearSolver(analysis_->linearSolverName());
  analysis_->assembler().restartContactSearch();
  const State& s = analysis_->state();
  log_ << "  SAVE   " << file.string() << ": step " << s.step << ", t = " << fmt("%.6e", s.t)
       << "\n";
}

void ProblemRun::restoreRestart(const Macro& m) {
  const std::filesystem::path file = restartPath(m);
  try {
    const std::string mine = loadRestart(file, model_, *analysis_, &input_);
    try {
      setRunState(mine);
    } catch (const CheckpointError& e) {
      throw CheckpointError("restart file '" + file.string() + "': " + e.what());
    }
  } catch (const CheckpointError& e) {
    throw AnalysisError(m.record.fieldLoc(0).str() + ": error: REST: " + e.what());
  }
  const State& s = analysis_->state();
  log_ << "  REST   " << file.string() << ": step " << s.step << ", t = " << fmt("%.6e", s.t)
       << ", " << model_.numNodes() << " nodes, " << model_.numElements() << " elements, "
       << analysis_->assembler().dofs().numEquations() << " equations\n";
}

}  // namespace c2d
