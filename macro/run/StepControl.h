#pragma once
// Step control (AUTO,CUT,dtmin,pred): what follows when a step's Newton loop
// ends unconverged (diverged, stalled, out of iterations) or a step cannot be
// committed. With step cutting the step goes back to the committed state and
// is taken again at half its length, down to dtmin; after two steps at a cut
// length it doubles back towards the nominal dt, and a path-following
// increment follows dt / nominal dt. Without it the run fails there, with the
// iterations and what to try.
#include <functional>
#include <ostream>
#include <string>

#include "core/Error.h"
#include "macro/deck/SolutionCommand.h"
#include "solvers/NewtonVerdict.h"

namespace c2d {

class Analysis;
class EnergyWatch;
struct Macro;

class StepControl {
 public:
  // `energy`: the run's energy watch, named in the advice of a failure.
  StepControl(std::ostream& log, const EnergyWatch& energy) : log_(log), energy_(energy) {}
  // The analysis whose steps are controlled (before any other call).
  void attach(Analysis& analysis) { analysis_ = &analysis; }

  // AUTO,CUT,dtmin,pred (on) or AUTO,CUT,off: dtmin 0 is the nominal dt / 1024;
  // with pred a dynamic step whose predicted start diverges is cut (from the
  // prediction again) rather than started again from the committed state.
  void set(bool on, double dtMin, bool cutDivergingPrediction);
  // DT: the nominal step, the one a cut step grows back to.
  void setNominal(double dt) { dtNominal_ = dt; }
  bool cutting() const { return cutting_; }
  int cuts() const { return cuts_; }

  // --- a step begins (TIME)
  // A cut step grows back: doubled (to at most the nominal dt) every second step.
  void growBack();
  // The path-following increment at dt / nominal dt under cutting, else 1: a cut
  // step is a cut path increment too (else the retried step would repeat the
  // same Newton history).
  void scalePathIncrement();
  // `st`: how the step began (Analysis::advance). A converged step that could
  // not be committed (an element cannot be evaluated at it) is, under cutting,
  // dropped and taken again in halves; returns the failure that remains (given
  // up below dtmin).
  Status cutUntilCommitted(Status st);

  // --- a Newton loop
  // A loop begins: no verdict, no failure yet.
  void loopBegins();
  // An iteration failed (a singular tangent, an element that cannot be
  // evaluated): under cutting logged, and the loop ends as diverged (true);
  // else false, and the run fails.
  bool iterationFailed(const std::string& why);
  // The step started again from the committed state after its predicted start
  // diverged: cut instead (AUTO,CUT,,1) while a half step is at least dtmin:
  // the loop ends as diverged (true).
  bool cutsDivergingPrediction();
  // The step is at its smallest with AUTO,CUT,,1, and below a thousandth of
  // the nominal one: a predicted start whose energy rises is no longer cut or
  // started again from u_n, and Newton goes on from it.
  bool atSmallestPredictedStep() const;
  // The loop ends on the verdict (Stalled or Diverged): recorded for its report.
  Flow ends(NewtonVerdict verdict);
  // The last iteration diverged: the loop's passes stop.
  bool diverged() const { return verdict_ == NewtonVerdict::Diverged; }
  // Parts of steps begun by Newton iterations (a landing time, an impact's
  // shorter step): each part has the loop's count of iterations.
  void partBegins() { ++parts_; }
  int parts() const { return parts_; }
  // Why the loop of `iterations` passes ended without convergence.
  std::string unconverged(int iterations) const;
  // A Newton loop ended without convergence (`why`): without cutting the run
  // fails (AnalysisError at the loop); with it the step is cut and `passes`
  // (the loop's passes again) run until the step converges, or fails below
  // dtmin. `iterations`: the loop's count.
  Flow retry(const Macro& loop, const std::string& why, int iterations,
             const std::function<Flow()>& passes);

  // The part of a restart file that is the step control's.
  struct Saved {
    bool cutting = false;
    double dtMin = 0, dtNominal = 0;
    int stepsSinceCut = 0, cuts = 0;
  };
  Saved saved() const { return {cutting_, dtMin_, dtNominal_, stepsSinceCut_, cuts_}; }
  void restore(const Saved& s);

 private:
  // Back to the committed state, the step cut to dt (a proposed shorter step
  // through an impact halved with it: solvers/ImpactSteps), counted and
  // logged, and begun again.
  Status cut(double dt);
  // The error of a loop that failed, with the step's iterations and advice.
  std::string failure(const Macro& loop, const std::string& what, const std::string& why,
                      int iterations) const;

  std::ostream& log_;
  const EnergyWatch& energy_;
  Analysis* analysis_ = nullptr;
  bool cutting_ = false;
  double dtMin_ = 0, dtNominal_ = 0;
  bool cutPrediction_ = false;  // a diverging predicted start cuts the step (AUTO,CUT,,1)
  int stepsSinceCut_ = 0;
  int cuts_ = 0;
  // How the loop's last iteration ended (Stalled, Diverged; else Iterating), and
  // why an iteration failed or diverged under cutting.
  NewtonVerdict verdict_ = NewtonVerdict::Iterating;
  std::string lastFailure_;
  int parts_ = 0;
};

}  // namespace c2d
