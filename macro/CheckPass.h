#pragma once
// The check pass of a deck (macro/DeckWalker.h): every problem of every pass
// of the top-level loops built and bound, nothing computed, so that every deck
// error is found before any computing; what names each run is noted (RunInfo),
// the study's size checked, and a signal stops the planning.
#include <vector>

#include "macro/DeckWalker.h"
#include "macro/deck/Warnings.h"

namespace c2d {

class CheckPass : public DeckWalker {
 public:
  // The log of the binding goes to `log` (a discarded stream); deck warnings to `warnings`.
  CheckPass(const SolutionCommands& commands, const DeckOptions& options, std::ostream& log,
            Warnings* warnings = nullptr)
      : DeckWalker(commands, options, log), warnings_(warnings) {}

  const std::vector<RunInfo>& infos() const { return infos_; }

 private:
  void problem(const Problem& p, Parameters& params) override;
  // An ensemble sample's drawn values: its draws, its step factor, its blast times.
  void noteDraws(RunInfo& info, const ProblemRun& run) const;

  Warnings* warnings_;
  std::vector<RunInfo> infos_;
};

}  // namespace c2d
