#pragma once
// Where softening hinges open during an analysis (core/Hinge.h).
//
// Elements never activate their own hinge. After a converged step in which the
// largest demand |M|/Mu of a closed hinge exceeds 1, the step is cut back to
// the point where the demand is 1 (regula falsi on the step fraction, each
// trial a Newton solve from the committed state: the load level in statics,
// the time in dynamics), that state is committed, that one hinge opens, the
// state is committed again (in dynamics the hinge opens in that one commit: a
// commit of zero length would move the joints' relative rotations), and the
// rest of the step is solved. So a uniform
// moment opens exactly one hinge, the peak of a load-displacement curve is a
// computed point, and in a collapse no member carries more than its ultimate
// moment beyond the location band.
//
// From above: every element is at or past its ultimate moment when the hinge
// opens, so the opening element's hinge is at its capacity and takes the
// softening branch (the bulk freezes at the plastic curvature of Mu, which
// from a state below Mu would lower the moment by EI/Kh times the gap and leave
// the hinge rigid), and the others, on their yield surface, take the elastic one.
#include <utility>
#include <Eigen/Core>
#include <vector>

#include "core/Error.h"
#include "core/Hinge.h"
#include "elements/LocalizationZones.h"

namespace c2d {

class Analysis;
struct IterationInfo;

class HingeEvents {
 public:
  explicit HingeEvents(Analysis& analysis) : an_(analysis) {}

  // The elements that can carry a softening hinge (through a joint's wrapper
  // too): (element index, ability); rebuilt when the topology changed.
  const std::vector<std::pair<int, HingeCarrier*>>& carriers();
  // The most critical closed hinge at the last evaluated state: demand |M|/Mu
  // (the lowest element number among ties to round-off).
  double maxDemand(int& element);
  // After a converged iteration: when a hinge passed Mu by more than the
  // location band, locates the event, opens the hinge and sets up the rest of
  // the step (info.converged false, info.hingeActivated set). `handled` tells
  // whether it did.
  Status afterConvergence(IterationInfo& info, bool lineSearch, bool& handled);
  // At every commit: the localization zones of the hinges open in the
  // committed state (elements/LocalizationZones.h), and its demand.
  void committed();
  bool locating() const { return locating_; }

  double committedDemand() const { return committedDemand_; }
  void setCommittedDemand(double d) { committedDemand_ = d; }

 private:
  Status locate(IterationInfo& info, bool lineSearch);
  // Its steps: the bracket [0, 1] of the step with the demands at its ends;
  // trials that narrow it until one lands in the band (or the trials run
  // out); the event's point solved (or the committed state kept) and
  // committed; the hinge opened there.
  struct Bracket;
  Bracket startBracket();
  Status bracketEvent(Bracket& b, double tEnd, bool lineSearch);
  // The bracket's side that the trial's demand d falls on moves to it.
  void narrow(Bracket& b, double d);
  Status reachEvent(Bracket& b, double tEnd, bool lineSearch);
  Status openEvent(const Bracket& b, IterationInfo& info);
  // Newton to the fraction `fraction` of the step ending at tEnd, from `start`
  // (the free dofs; null: the committed state), in at most maxIterations.
  Status solveFraction(double fraction, double tEnd, bool lineSearch,
                       const Eigen::VectorXd* start = nullptr, int maxIterations = 60);
  // solveFraction from the interpolation of the bracket's converged ends, and
  // from the committed state when that has not converged in a few iterations
  // (dynamic steps).
  Status solveBetween(double fraction, double sLo, double sHi, double tEnd, bool lineSearch);
  void open(int element);
  // Opens the hinge at end `end` of the element whatever its demand
  // (HingeCarrier::activateHingeAt).
  void openAt(int element, int end);
  // The committed state as the end of a sub-step of zero length (the event is
  // at the committed state).
  void restoreCommitted();
  // Evaluates the element whose hinge was just opened at the committed state.
  Status evaluateOpened(int element);
  // Commits the end of a located sub-step; an internal error unless that end
  // is a converged solve or the committed state.
  Status commitSolved();

  Analysis& an_;
  std::vector<std::pair<int, HingeCarrier*>> carriers_;
  int carriersVersion_ = -1;
  LocalizationZones zones_;     // one softening hinge per localization zone
  double committedDemand_ = 0;  // max demand at the last commit
  bool locating_ = false;       // inside locate(): no nested events
  bool solved_ = false;         // the state is the converged end of a sub-step
  // Displacements of the bracket's converged ends (the committed state and the
  // step's end at first) and the start interpolated between them.
  Eigen::VectorXd uLo_, uHi_, start_;
};

}  // namespace c2d
