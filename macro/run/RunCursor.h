#pragma once
// Where a run is in its command tree (the BATCh blocks' commands, LOOPs with
// their bodies), and what it does once the loop running now has ended: the
// rule that decides whether a TIME,,tmax ends its loop exactly on tmax.
//
// A loop that TIME,,tmax ends lands its last step on tmax (the step
// shortened) when the loop ends a phase: when the first command the run meets
// after the loop, passing over outputs, changes the model or the analysis
// (MESH, HINGe2joint, REMOve, DYNAmic, DT, AUTO, PROP, ARCL, TOL, BACK, a
// Newton command, FORM), or when the run ends there (a push to a load level,
// a fall to a given time, end on it). When it meets a TIME first (the next
// pass of a picture loop, another time loop) or a SAVE (a checkpoint, from
// which a REST continues the motion as the uninterrupted run does), the loop
// ends with the step that reaches or passes tmax, as if the loops were one,
// and the outputs in between show the motion at tmax
// (solvers/DenseOutput.h). Outputs are PLOT, PVIEw, TPLOt, the printed tables
// (DISP, VELO, ACCE, REAC, STRE), FORM,LONG/SHORt, PARAmeter and REST (which
// replaces the state anyway): the number and the times of a run's pictures,
// frames and tables never change its steps.
#include <cstddef>
#include <optional>
#include <vector>

#include "macro/deck/Macro.h"
#include "macro/deck/Parameters.h"

namespace c2d {

class RunCursor {
 public:
  // What the run meets first after the loop running now, outputs passed over.
  enum class Next {
    Step,    // a TIME or a SAVE: the motion goes on
    Change,  // a command that changes the model or the analysis: the phase ends
    End,     // the run ends (its last command, or STOP)
  };

  // The BATCh blocks of the run, in order (borrowed; they outlive the cursor's use).
  void reset(const std::vector<std::vector<Macro>>& batches);

  // A command list starts running until the scope ends: a BATCh block, or pass
  // `pass` (0-based) of `passes` of a loop's body.
  class Scope {
   public:
    Scope(RunCursor& cursor, const std::vector<Macro>& list, bool loopBody, int pass, int passes);
    ~Scope();
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    RunCursor& cursor_;
  };
  // The command at `index` of the innermost list is about to run.
  void at(std::size_t index) { frames_.back().index = index; }

  // Whether the loop that TIME,,tmax ends lands on tmax (Change or End).
  static bool lands(Next next) { return next != Next::Step; }
  // What follows the loop that holds the command running now (a command of a
  // BATCh block outside any loop: what follows that command). Loop counts are
  // evaluated with `params`.
  Next afterLoop(const Parameters& params) const;

 private:
  struct Frame {
    const std::vector<Macro>* list = nullptr;
    std::size_t index = 0;
    bool loopBody = false;
    int pass = 0, passes = 1;
  };
  // What the first command of `list` from `from` on that is not an output
  // means (inside the loops it meets with a positive count); none: the list
  // holds outputs only from there.
  std::optional<Next> scan(const std::vector<Macro>& list, std::size_t from,
                           const Parameters& params) const;

  const std::vector<std::vector<Macro>>* batches_ = nullptr;
  std::vector<Frame> frames_;
};

}  // namespace c2d
