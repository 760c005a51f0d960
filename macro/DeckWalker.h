#pragma once
// The walk over a deck's top-level items (PARAmeter blocks, problems, LOOPs,
// SWEEps, ENSEmbles) that both passes of a deck share: the check pass
// (CheckPass.h: every problem bound, its run named, nothing computed) and the
// execute pass (ExecutePass.h: every problem bound and run). The walk keeps the
// study's context of the problem at hand (the swept values, the ensemble's
// sample) and the size of the study; the passes say what a problem is to them.
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "macro/DeckRunner.h"
#include "macro/deck/Deck.h"
#include "macro/draws/Ensemble.h"
#include "macro/studies/EnsembleTable.h"
#include "macro/studies/StudySize.h"
#include "macro/draws/Sweep.h"
#include "macro/run/ProblemRun.h"

namespace c2d {

// What the check pass learns about each run, to name it before anything runs.
struct RunInfo {
  SweepValues sweep;                     // empty outside a SWEEp
  std::string planName;                  // the SWEEp's PLAN name of its value set, if any
  std::map<std::string, double> params;  // the parameter table as the problem starts
  int plan = 0;                          // an ensemble's plan (1-based), 0 outside one
  int sample = 0, samples = 0;           // its sample 1..samples, 0 outside an ensemble
  DrawnValues drawn;                     // the sample's drawn values
  std::vector<std::string> zones;        // the site's protected zones (SITE)
};

// Output stem and legend label of each run, and what an ensemble's table says of it.
struct RunPlan {
  std::string stem, label;
  int plan = 0, sample = 0;
  DrawnValues drawn;
  std::string planName;  // the SWEEp's PLAN name, if any
};

// A named plan's label is its name; else its swept values.
std::string planLabel(const SweepValues& sweep, const std::string& name);

class DeckWalker {
 public:
  virtual ~DeckWalker() = default;
  DeckWalker(const DeckWalker&) = delete;
  DeckWalker& operator=(const DeckWalker&) = delete;

  void walk(const std::vector<TopItem>& items, Parameters& params);

  // The problems walked (every one, also those a shard leaves to the others).
  int runs() const { return runs_; }
  // The first ENSEmble record walked, if any.
  const Record* ensembleHead() const { return ensembleHead_; }
  // The title of the last problem walked.
  const std::string& title() const { return title_; }

 protected:
  DeckWalker(const SolutionCommands& commands, const DeckOptions& options, std::ostream& log)
      : commands_(commands), options_(options), log_(log) {}

  // A problem of the deck in the walk's context; it calls counted(p) once it is a run.
  virtual void problem(const Problem& p, Parameters& params) = 0;
  // The problem is the runs_-th run (1-based) and the last title.
  void counted(const Problem& p);
  // The options every run of the deck has (output directory, solver, the sample).
  RunOptions runOptions() const;

  const SolutionCommands& commands_;
  const DeckOptions& options_;
  std::ostream& log_;
  // The context of the problem at hand.
  SweepValues sweep_;
  std::string planName_;                 // the PLAN name of the sweep's value set walked
  const SampleDraws* sample_ = nullptr;  // the ensemble's sample being walked
  int samples_ = 0, plan_ = 0;           // its sample count; the ensemble plans walked
  const Record* detonators_ = nullptr;   // the DETOnators record of the ensemble walked
  int runs_ = 0;
  StudySize size_;  // the passes of the LOOPs, SWEEps and ENSEmble being walked

 private:
  void walkLoop(const TopLoop& loop, Parameters& params);
  void walkSweep(const TopSweep& sweep, Parameters& params);
  // Every sample of the ensemble runs the body (PARAmeter blocks, the problem)
  // from the same parameter table, with its drawn values set (and protected).
  void walkEnsemble(const TopEnsemble& e, Parameters& params);

  EnsemblePairing pairing_;  // the same n and seed in every plan
  const Record* ensembleHead_ = nullptr;
  std::string title_;
};

}  // namespace c2d
