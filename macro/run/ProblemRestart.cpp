// ProblemRun's restart files (SAVE, REST): the run's own state beside the
// model's and the analysis', written and read back.
#include "elements/Joints.h"
#include "macro/run/ProblemRun.h"
#include "macro/run/RunState.h"
#include "solvers/RestartFile.h"

namespace c2d {

// ------------------------------------------------------------------ restart

std::filesystem::path ProblemRun::restartPath(const Macro& m) const {
  std::string name = m.optionText.empty() ? options_.stem : m.optionText;
  if (std::filesystem::path(name).extension() != ".rst") name += ".rst";
  return options_.outDir / name;
}

void ProblemRun::saveRestart(const Macro& m) {
  const Status st = analysis_->commit();
  if (!st) fail(m, st.why);
  const std::filesystem::path file = restartPath(m);
  try {
    c2d::saveRestart(file, model_, *analysis_, runStateBytes(watches_, steps_), input_);
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
      readRunState(mine, model_, watches_, steps_);
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
