#pragma once
// The run's watches and counters, kept at every commit and event of a run:
// hinges formed (and when), topology events, removed elements, the largest
// |M|/Mu (CapacityWatch), the energy balance (EnergyWatch), the peak ground
// force and the deepest node, the kinetic energy's peak (TIME,REST's rest
// detection), and at the end the members crossing or folded and the blasts
// not made. They give the run's summary (RunSummary) and the log's warnings
// of these; the restart file keeps them (Saved).
#include <istream>
#include <optional>
#include <ostream>
#include <vector>

#include "macro/output/Debris.h"
#include "core/Hinge.h"
#include "macro/run/CapacityWatch.h"
#include "macro/run/EnergyWatch.h"
#include "macro/run/RunSummary.h"
#include "macro/run/TopologyLog.h"

namespace c2d {

class Analysis;
struct RemovalEvent;
struct State;

class RunWatches {
 public:
  RunWatches(std::ostream& log, const Model& model) : log_(log), model_(model) {}
  // The analysis watched (before any other call): the hinge steps sized to its model.
  void attach(Analysis& analysis);

  // --- events of the analysis (logged and counted)
  void hingeActivated(int element, const HingeInfo& h);
  void topologyEvent(const TopologyEvent& ev);
  // Removed elements (BLASt, REMOve): counted, logged (a blast that removed nothing warned).
  void removal(const RemovalEvent& ev);
  // The elements changed (MESH re-entry, HINGe2joint, REMOve): the hinge steps follow.
  void elementsChanged();

  // At a commit: the hinges formed (logged) and |M|/Mu (CapacityWatch)...
  void observeHinges();
  // ... then, with its energy `en`: the ground force and depth, the energy
  // balance, the kinetic energy's peak.
  void observeMotion(const Energy& en);

  // TIME,REST's test: the ratio of the kinetic energy's peak and the time it
  // must hold.
  struct Rest {
    double ratio = 1e-5, hold = 0.5;
  };
  // TIME,REST: the motion is at rest at the committed state when the kinetic
  // energy has stayed at or below `ratio` of its peak for `hold` time units
  // (logged once); a new ratio is watched from now on.
  bool atRestNow(const Rest& rest);
  // TIME,REST ended a loop at rest and no step has been taken since.
  bool atRest() const;

  // The debris figures of the state s, with the run's peak ground force,
  // deepest node and kinetic energy against its peak.
  DebrisFigures debrisNow(const State& s) const;
  // The end's debris figures (a run that ended with ground contact).
  void setDebris(const DebrisFigures& d) { debris_ = d; }
  const std::optional<DebrisFigures>& debris() const { return debris_; }

  // At the end of the run: members crossing each other or folded beyond a
  // quarter turn, the topology lines folded, the blasts not made (log warnings).
  void reportEnd();

  // The run's summary: its steps, iterations and factorizations, `cuts`, the
  // wall time `seconds` and these watches' figures.
  RunSummary summary(int cuts, double seconds) const;

  // The step at which each element's hinge formed (0: none), the STRE table's.
  const std::vector<int>& hingeSteps() const { return hingeStep_; }
  int hinges() const { return hingeCount_; }
  const EnergyWatch& energy() const { return energy_; }

  // The watches' part of a restart file (the energy watch saves itself).
  struct Saved {
    std::vector<int> hingeStep;
    int hingeCount = 0;
    double maxMomentRatio = 0, peakGroundForce = 0, peakGroundTime = 0;
    double peakKinetic = 0, restRatio = 0, lastMoving = 0;
    GroundDepth deepest;
    double deepestTime = 0;
    int jointsFormed = 0, jointsRuptured = 0, removed = 0, hinges = 0, fractures = 0, shears = 0;
    bool dynamicSeen = false;
  };
  Saved saved() const;
  void restore(const Saved& s);
  void saveEnergy(std::ostream& out) const { energy_.save(out); }
  void loadEnergy(std::istream& in) { energy_.load(in); }

 private:
  void reportCrossings();
  void reportFolds();

  std::ostream& log_;
  const Model& model_;
  Analysis* analysis_ = nullptr;
  std::vector<int> hingeStep_;  // step at which each element's hinge formed
  int hingeCount_ = 0;
  TopologyCounts topology_;
  int removed_ = 0;
  int crossings_ = 0;
  int folded_ = 0;
  int blastsNotMade_ = 0;
  CapacityWatch capacity_;
  EnergyWatch energy_;
  bool dynamicSeen_ = false;
  // TIME,REST: the kinetic energy's peak, the ratio watched (0: none yet) and
  // the last committed time at which the kinetic energy was above it.
  double peakKinetic_ = 0, restRatio_ = 0, lastMoving_ = 0;
  bool restLogged_ = false;
  double restTime_ = 0;  // when TIME,REST last ended a loop at rest
  // Debris: the largest total ground force so far and its time; the figures at the end.
  double peakGroundForce_ = 0, peakGroundTime_ = 0;
  // The deepest any node went into the ground, and when.
  GroundDepth deepest_;
  double deepestTime_ = 0;
  std::optional<DebrisFigures> debris_;
};

}  // namespace c2d
