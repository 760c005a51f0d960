// ProblemRun's Newton iterations (TANG, UTAN, FORM, SOLV): an iteration with
// its log line and its stall and cycle tests, a step cut and taken again when
// its loop ends unconverged, and the advice a failure gives.
#include <algorithm>
#include <cstdio>
#include <sstream>

#include "macro/run/ProblemRun.h"
#include "solvers/NewtonVerdict.h"

namespace c2d {

std::string ProblemRun::historyText() const {
  std::ostringstream os;
  os << "    iteration      residual   energy |du.R|\n";
  for (const IterationInfo& i : analysis_->stepHistory()) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "    %9d  %12.5e  %12.5e\n", i.iteration, i.residual, i.energy);
    os << buf;
  }
  int node = -1, dof = -1;
  const double r = analysis_->largestResidual(node, dof);
  if (node >= 0)
    os << "    largest residual " << fmt("%.5e", r) << " at node " << node + 1 << ", dof "
       << dof + 1 << "\n";
  return os.str();
}

std::string ProblemRun::advice(const std::string& why, bool lineSearch, int iterations) const {
  std::ostringstream os;
  if (energy_.gainStep() > 0)
    os << "    " << energyGainText(energy_.gained(), energy_.gainStep(), energy_.gainTime())
       << "\n";
  os << "    to try:";
  if (why.find("singular") != std::string::npos) {
    os << " the model may be a mechanism or have lost all stiffness somewhere: check the "
          "BOUNdary codes, joints and released hinges near the node named;";
  }
  if (analysis_->pathFollowing())
    os << " a smaller path increment (ARCL data)";
  else
    os << " a smaller step (DT,,dt)";
  if (!cutting_)
    os << ", step cutting (AUTO,CUT,dtmin)";
  else
    os << ", a smaller dtmin (AUTO,CUT,dtmin)";
  if (!lineSearch && !analysis_->pathFollowing()) os << ", a line search (TANG,LINE,1)";
  if (iterations > 0) os << ", more iterations (LOOP,," << 2 * iterations << ")";
  os << ", a looser tolerance (TOL,,etol,rtol)\n";
  return os.str();
}

namespace {

// The loop's Newton command uses the line search (TANG,LINE,1).
bool usesLineSearch(const Macro& loop) {
  for (const Macro& b : loop.body)
    if ((b.is("tang") || b.is("utan")) && b.option.rfind("line", 0) == 0) return true;
  return false;
}

}  // namespace

Status ProblemRun::cutStep(double dt) {
  ++cuts_;
  stepsSinceCut_ = 0;
  analysis_->back();
  analysis_->setDt(dt);
  analysis_->impactSteps().cut(dt);
  scalePathIncrement();
  log_ << "  cut    step to dt = " << fmt("%.4e", dt) << "\n";
  return analysis_->advance();
}

Flow ProblemRun::retryWithCut(const Macro& loop, const std::string& why) {
  const State& s = analysis_->state();
  std::ostringstream msg;
  msg << "Newton iteration " << why << " in step " << s.step + 1 << " (t = " << fmt("%.6e", s.t)
      << ", dt = " << fmt("%.4e", s.dt) << ")";
  log_ << "  *** " << msg.str() << "\n" << historyText();
  const int iterations = loop.has(0) ? loop.numbers[0].evalInt(params_, "loop count") : 1;
  const bool unconverged = why.rfind("did not converge", 0) == 0;
  if (!cutting_)
    throw AnalysisError(loop.record.fieldLoc(0).str() + ": error: " + msg.str() + "\n" +
                        historyText() +
                        advice(why, usesLineSearch(loop), unconverged ? iterations : 0));
  for (;;) {
    const double dt = 0.5 * analysis_->state().dt;
    if (dt < dtMin_)
      throw AnalysisError(loop.record.fieldLoc(0).str() + ": error: " + msg.str() +
                          "; step cutting gave up at the minimum step " + fmt("%.4e", dtMin_) +
                          "\n" + historyText() +
                          advice(why, usesLineSearch(loop), unconverged ? iterations : 0));
    const Status st = cutStep(dt);
    if (!st) throw AnalysisError(loop.record.fieldLoc(0).str() + ": error: " + st.why);
    const int n = loop.has(0) ? loop.numbers[0].evalInt(params_, "loop count") : 1;
    diverged_ = stalled_ = false;
    for (int i = 0, part = parts_; i < n; ++i) {
      const Flow f = execList(loop.body, false, i, n);
      if (f == Flow::Stop) return f;
      if (f == Flow::ExitLoop || diverged_) break;
      if (parts_ != part) i = -1, part = parts_;
    }
    if (analysis_->stepConverged()) return Flow::Next;
  }
}

Flow ProblemRun::newtonIteration(const Macro& m, bool update, bool lineSearch, bool symmetric) {
  if (!update) {
    const Status st = analysis_->formTangent(symmetric);
    if (!st) fail(m, st.why);
    log_ << "  TANG   tangent formed\n";
    return Flow::Next;
  }
  IterationInfo info;
  const Status st = analysis_->iterate(lineSearch, symmetric, info);
  const State& s = analysis_->state();
  if (!st) {
    if (cutting_) {
      log_ << "  *** " << st.why << "\n";
      lastFailure_ = st.why;
      diverged_ = true;
      return Flow::ExitLoop;
    }
    fail(m, st.why + "\n" + historyText() + advice(st.why, lineSearch, 0));
  }
  // From u_n the inertia residual of a fast fall is that of the whole velocity
  // (first energies 1e3-1e4 against 1e1-1e2 from the prediction), and after
  // a hinge event or a joint Newton's method often wanders from there until
  // the loop ends and the step is cut anyway: a half step from the prediction
  // is cheaper. At the smallest step the restart stays the last resort.
  if (info.restarted && cutting_ && cutPrediction_ && 0.5 * s.dt >= dtMin_) {
    lastFailure_ = "the predicted start diverges";
    diverged_ = true;
    return Flow::ExitLoop;
  }
  if (info.restarted) {
    log_ << "  " << (symmetric ? "TANG " : "UTAN ") << "  step " << s.step + 1
         << ": the predicted start diverges; the step starts again from the committed state\n";
    return Flow::Next;
  }
  char buf[160];
  std::snprintf(buf, sizeof buf,
                "  %-5s  step %5d  t = %12.5e  it %3d  |R| = %11.4e  |du.R| = %11.4e%s\n",
                symmetric ? "TANG" : "UTAN", s.step + 1, s.t, info.iteration, info.residual,
                info.energy, info.converged || info.subStep ? "  converged" : "");
  log_ << buf;
  // A part of the step begins: committed at a landing time, or taken again
  // shorter through an impact (solvers/ImpactSteps.h).
  if (info.subStep) {
    ++parts_;
    sample_.partCommitted(s);
    if (info.shortened > 0)
      log_ << "  " << (symmetric ? "TANG " : "UTAN ") << "  step " << s.step + 1
           << ": a contact needs a shorter step through its impact: taken again with h = "
           << fmt("%.4e", info.shortened) << "\n";
    return Flow::Next;
  }
  const NewtonVerdict verdict = newtonVerdict(info, analysis_->stepHistory());
  if (verdict == NewtonVerdict::Diverged) {
    diverged_ = true;
    return Flow::ExitLoop;
  }
  if (info.globalized)
    log_ << "  " << (symmetric ? "TANG " : "UTAN ") << "  step " << s.step + 1
         << ": Newton's iterates cycle (energy or residual repeating with a period of one to "
            "six) or run away (the residual growing); the line search of TANG,LINE takes over\n";
  // Stalled: the step is cut (or reported) now, not at the end of the loop.
  if (verdict == NewtonVerdict::Stalled) {
    stalled_ = true;
    return Flow::ExitLoop;
  }
  return verdict == NewtonVerdict::Converged ? Flow::ExitLoop : Flow::Next;
}

Flow ProblemRun::formResidual(const Macro& m) {
  double norm = 0;
  const Status st = analysis_->formResidual(norm);
  if (!st) fail(m, st.why);
  log_ << "  FORM   |R| = " << fmt("%.6e", norm) << "\n";
  return Flow::Next;
}

Flow ProblemRun::solveOnly(const Macro& m) {
  IterationInfo info;
  const Status st = analysis_->solveOnly(info);
  if (!st) fail(m, st.why);
  log_ << "  SOLV   it " << info.iteration << "  |du.R| = " << fmt("%.4e", info.energy)
       << (info.converged ? "  converged\n" : "\n");
  return info.converged ? Flow::ExitLoop : Flow::Next;
}

}  // namespace c2d
