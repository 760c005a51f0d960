// ProblemRun's Newton iterations (TANG, UTAN, FORM, SOLV): an iteration with
// its log line and its verdict (solvers/NewtonVerdict.h); what an unconverged
// loop leads to is the step control's (StepControl.h).
#include <cstdio>

#include "macro/run/NewtonReport.h"
#include "macro/run/ProblemRun.h"
#include "solvers/NewtonVerdict.h"

namespace c2d {

Flow ProblemRun::newtonIteration(const Macro& m, bool update, bool lineSearch, bool symmetric) {
  if (!update) {
    const Status st = analysis_->formTangent(symmetric);
    if (!st) fail(m, st.why);
    log_ << "  TANG   tangent formed\n";
    return Flow::Next;
  }
  IterationInfo info;
  analysis_->keepPrediction(steps_.atSmallestPredictedStep());
  const Status st = analysis_->iterate(lineSearch, symmetric, info);
  const State& s = analysis_->state();
  if (!st) {
    if (steps_.iterationFailed(st.why)) return Flow::ExitLoop;
    fail(m, st.why + "\n" + newtonHistoryText(*analysis_) +
                newtonAdvice(*analysis_, watches_.energy(), steps_.cutting(), st.why, lineSearch, 0));
  }
  if (info.restarted && steps_.cutsDivergingPrediction()) return Flow::ExitLoop;
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
    steps_.partBegins();
    sample_.partCommitted(s);
    if (info.shortened > 0)
      log_ << "  " << (symmetric ? "TANG " : "UTAN ") << "  step " << s.step + 1
           << ": a contact needs a shorter step through its impact: taken again with h = "
           << fmt("%.4e", info.shortened) << "\n";
    return Flow::Next;
  }
  const NewtonVerdict verdict = newtonVerdict(info, analysis_->stepHistory());
  if (verdict == NewtonVerdict::Diverged) return steps_.ends(verdict);
  if (info.globalized)
    log_ << "  " << (symmetric ? "TANG " : "UTAN ") << "  step " << s.step + 1
         << ": Newton's iterates cycle (energy or residual repeating with a period of one to "
            "six) or run away (the residual growing); the line search of TANG,LINE takes over\n";
  // Stalled: the step is cut (or reported) now, not at the end of the loop.
  if (verdict == NewtonVerdict::Stalled) return steps_.ends(verdict);
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
