#pragma once
// The execute pass of a deck (macro/DeckWalker.h): every problem bound again
// and run, under the stem and label the check pass planned for it (a shard
// runs every n-th only). A run of a study (SWEEp, ENSEmble) that fails is
// reported in the study's table and the study goes on; elsewhere a failure
// ends the deck, its outputs kept under tagged names. The runs' summaries
// add up to the deck's (RunSummary), their curves to the overlay.
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "macro/DeckWalker.h"
#include "macro/studies/CurveOverlay.h"
#include "macro/studies/EnsembleTable.h"
#include "macro/studies/PlanTable.h"

namespace c2d {

class ExecutePass : public DeckWalker {
 public:
  // `console`: where a study's runs' summaries and failures go (null: nowhere).
  ExecutePass(const SolutionCommands& commands, const DeckOptions& options, std::ostream& log,
              std::ostream* console, std::vector<RunPlan> plans, std::string stem)
      : DeckWalker(commands, options, log),
        console_(console),
        plans_(std::move(plans)),
        stem_(std::move(stem)) {}

  const RunSummary& total() const { return total_; }
  const CurveOverlay& overlay() const { return overlay_; }
  // The study's table: set before walking when the deck has a SWEEp.
  void setPlanTable(PlanTable table) { planTable_ = std::move(table); }
  const std::optional<PlanTable>& planTable() const { return planTable_; }
  // The ensemble's table: set before walking when the deck has an ENSEmble.
  void setEnsembleTable(EnsembleTable table) { ensembleTable_ = std::move(table); }
  const std::optional<EnsembleTable>& ensembleTable() const { return ensembleTable_; }
  // The runs of a study that failed.
  int failed() const { return failed_; }
  // The outputs a failed or interrupted run kept (tagged names).
  const std::vector<std::filesystem::path>& kept() const { return kept_; }

 private:
  void problem(const Problem& p, Parameters& params) override;
  // The run's options and its log's head (title, stem, drawn values).
  RunOptions begin(const Problem& p, const RunPlan& plan, bool brief);
  // Bind and run; a study's run that fails with a deck or analysis error is
  // noted in `row` (false: the deck goes on), every other failure thrown.
  void execute(ProblemRun& run, PlanRow& row, bool inStudy);
  // The run's summary and warnings in the log, on the console and on standard error.
  void report(const RunSummary& s, const std::string& stem);

  std::ostream* console_;
  std::vector<RunPlan> plans_;
  std::string stem_;
  RunSummary total_;
  CurveOverlay overlay_;
  std::optional<PlanTable> planTable_;
  std::optional<EnsembleTable> ensembleTable_;
  int failed_ = 0;
  std::vector<std::filesystem::path> kept_;
};

}  // namespace c2d
