#include "macro/run/RunWatches.h"

#include <algorithm>
#include <cmath>

#include "core/contact/MemberCrossing.h"
#include "elements/EndHinges.h"
#include "elements/MemberFold.h"
#include "macro/output/NumberText.h"
#include "macro/run/RemovalLog.h"
#include "solvers/Analysis.h"

namespace c2d {

void RunWatches::attach(Analysis& analysis) {
  analysis_ = &analysis;
  hingeStep_.assign(model_.numElements(), 0);
}

void RunWatches::hingeActivated(int e, const HingeInfo& h) {
  log_ << "  " << (h.shear ? "shear  element " : h.fracture ? "bars   element " : "hinge  element ")
       << e + 1 << " activated at t = " << formatNumber("%.6e", analysis_->state().t)
       << (h.shear      ? ": shear at its capacity Vu(N)"
           : h.fracture ? ": fracture strain"
                        : ", M = " + formatNumber("%.6e", h.moment))
       << "\n";
}

void RunWatches::topologyEvent(const TopologyEvent& ev) {
  hingeStep_.resize(model_.numElements(), 0);
  if (ev.kind == TopologyEvent::Kind::HingeOpened && hingeStep_[ev.element] == 0)
    hingeStep_[ev.element] = analysis_->state().step;
  logTopologyEvent(log_, model_, analysis_->state().t, ev, topology_);
}

void RunWatches::removal(const RemovalEvent& ev) {
  removed_ += static_cast<int>(ev.elements.size());
  const RemovalLog line = removalLog(ev);
  blastsNotMade_ += line.warning ? 1 : 0;
  log_ << line.text;
}

void RunWatches::elementsChanged() { hingeStep_.resize(model_.numElements(), 0); }

void RunWatches::observeHinges() {
  const State& s = analysis_->state();
  for (const auto& [e, h] : analysis_->hingeCarriers()) {
    if (hingeStep_[e] != 0) continue;
    const HingeInfo info = h->hinge();
    if (!info.active) continue;
    hingeStep_[e] = s.step;
    ++hingeCount_;
    log_ << "  hinge  formed in element " << e + 1 << " at step " << s.step
         << " (t = " << formatNumber("%.6e", s.t) << ", M = " << formatNumber("%.6e", info.moment)
         << ")\n";
  }
  for (const auto& [e, h] : analysis_->hingeCarriers()) {
    const HingeInfo info = h->hinge();
    if (info.ultimate > 0) capacity_.observe(e, std::abs(info.moment) / info.ultimate, s.t, log_);
  }
  int endElement = -1;
  const double endRatio = endHingeRatio(model_, &endElement);
  capacity_.observe(endElement, endRatio, s.t, log_);
}

void RunWatches::observeMotion(const Energy& en) {
  const State& s = analysis_->state();
  if (model_.ground()) {
    const double f = groundForce(model_, analysis_->assembler().dofs(), s);
    if (f > peakGroundForce_) {
      peakGroundForce_ = f;
      peakGroundTime_ = s.t;
    }
    if (const GroundDepth d = deepestNode(model_, analysis_->assembler().dofs(), s);
        d.node >= 0 && d.depth > deepest_.depth) {
      deepest_ = d;
      deepestTime_ = s.t;
    }
  }
  dynamicSeen_ = dynamicSeen_ || analysis_->integrator().dynamic();
  energy_.onCommit(en, analysis_->integrator().dynamic(), s.step, s.t);
  if (analysis_->integrator().dynamic()) {
    peakKinetic_ = std::max(peakKinetic_, en.kinetic);
    if (en.kinetic > restRatio_ * peakKinetic_) lastMoving_ = s.t;
  }
}

bool RunWatches::atRestNow(const Rest& rest) {
  const State& s = analysis_->state();
  // A new ratio is watched from now on.
  if (rest.ratio != restRatio_) {
    restRatio_ = rest.ratio;
    lastMoving_ = s.t;
  }
  const double kinetic = analysis_->kineticEnergy();
  if (!(peakKinetic_ > 0 && kinetic <= restRatio_ * peakKinetic_ && s.t - lastMoving_ >= rest.hold))
    return false;
  if (!restLogged_)
    log_ << "  TIME   at rest at t = " << formatNumber("%.6e", s.t) << ": the kinetic energy "
         << formatNumber("%.4e", kinetic) << " has stayed at most " << formatNumber("%.1e", restRatio_)
         << " of its peak " << formatNumber("%.4e", peakKinetic_)
         << " since t = " << formatNumber("%.6e", lastMoving_) << "\n";
  restLogged_ = true;
  restTime_ = s.t;
  return true;
}

bool RunWatches::atRest() const { return restLogged_ && analysis_->state().t == restTime_; }

DebrisFigures RunWatches::debrisNow(const State& s) const {
  DebrisFigures d = debrisFigures(model_, s);
  d.peakGroundForce = peakGroundForce_;
  d.peakTime = peakGroundTime_;
  d.kineticRatio = peakKinetic_ > 0 ? analysis_->kineticEnergy() / peakKinetic_ : 0.0;
  d.restRatio = restRatio_ > 0 ? restRatio_ : Rest{}.ratio;
  if (deepest_.node >= 0) {
    d.deepestNode = deepest_.node;
    d.deepest = deepest_.depth;
    d.deepestTime = deepestTime_;
    d.deepestLimit = halfSectionDepth(model_, deepest_.node);
  }
  return d;
}

void RunWatches::reportEnd() {
  reportCrossings();
  reportFolds();
  log_ << topology_.folding.summary();
  // A blast plan the run did not reach is not silently dropped.
  for (const Blast& b : model_.blasts())
    if (!b.done) {
      ++blastsNotMade_;
      log_ << "  warning: the blast at t = " << formatNumber("%.6e", b.time)
           << " did not happen: the run ended at t = " << formatNumber("%.6e", analysis_->state().t)
           << "\n";
    }
}

void RunWatches::reportCrossings() {
  // Members that passed through each other (core/contact/MemberCrossing.h).
  const std::vector<MemberCrossing> crossings = findCrossings(model_, analysis_->state());
  crossings_ = static_cast<int>(crossings.size());
  const std::size_t shown = std::min<std::size_t>(crossings.size(), 20);
  for (std::size_t i = 0; i < shown; ++i) {
    const MemberCrossing& c = crossings[i];
    log_ << (i == 0 ? "\n" : "") << "  warning: members " << c.first + 1 << " and " << c.second + 1
         << " cross at t = " << formatNumber("%.6e", analysis_->state().t) << ", at ("
         << formatNumber("%.3f", c.point.x()) << ", " << formatNumber("%.3f", c.point.y())
         << ") m: " << formatNumber("%.3f", c.fromNode[0]) << " m from node " << c.nearNode[0] + 1 << " and "
         << formatNumber("%.3f", c.fromNode[1]) << " m from node " << c.nearNode[1] + 1 << "\n";
  }
  if (crossings.size() > shown)
    log_ << "  warning: " << crossings.size() - shown << " more pairs of members cross\n";
  // Members that went through each other during the run, whatever the end.
  if (const Assembler& a = analysis_->assembler(); a.pushedThrough() > 0)
    log_ << "  warning: " << a.pushedThrough()
         << " times a node in contact with a member was pushed past its centre line ("
         << formatNumber("%.3e", a.pushedThroughEnergy())
         << " kJ of contact energy released): the member contact is too soft for the impact, or "
            "the pieces of a ruptured joint slid through each other\n";
}

void RunWatches::reportFolds() {
  // RC members folded beyond what a member does whole (elements/MemberFold.h).
  const std::vector<MemberFold> folds = foldedMembers(model_, analysis_->state());
  folded_ = static_cast<int>(folds.size());
  for (std::size_t i = 0; i < std::min<std::size_t>(folds.size(), 20); ++i)
    log_ << (i == 0 && crossings_ == 0 ? "\n" : "") << "  warning: member " << folds[i].element + 1
         << " is bent through " << formatNumber("%.3f", folds[i].fold) << " rad between its ends (nodes "
         << folds[i].nodes[0] + 1 << " and " << folds[i].nodes[1] + 1
         << ") at t = " << formatNumber("%.6e", analysis_->state().t)
         << ": more than a quarter turn, which no RC member bends whole"
         << (folds[i].failedHinge ? " (about its failed hinge, which made no joint: the member "
                                    "had a joint at an end, or the hinge lies within the "
                                    "shortest piece Lb of a joint or a free end)"
                                  : "")
         << "\n";
}

RunSummary RunWatches::summary(int cuts, double seconds) const {
  RunSummary s;
  s.steps = analysis_->state().step;
  s.iterations = analysis_->totalIterations();
  s.factorizations = analysis_->totalFactorizations();
  s.cuts = cuts;
  s.hinges = hingeCount_ + topology_.hinges;
  s.energyError = energy_.error();
  s.energyGained = energy_.gained();
  s.gainStep = energy_.gainStep();
  s.gainTime = energy_.gainTime();
  s.seconds = seconds;
  s.dynamic = dynamicSeen_;
  s.maxMomentRatio = capacity_.maxRatio();
  s.jointsFormed = topology_.jointsFormed;
  s.jointsRuptured = topology_.jointsRuptured;
  s.fractures = topology_.fractures;
  s.shears = topology_.shears;
  s.removed = removed_;
  s.crossings = crossings_;
  s.folded = folded_;
  s.sunk = debris_ && debris_->sunk() ? 1 : 0;
  s.memberContact = crossings_ > 0 && model_.memberContact().has_value();
  s.blastsNotMade = blastsNotMade_;
  s.debrisRuns = debris_ ? 1 : 0;
  s.outsideRuns = debris_ && debris_->outside() ? 1 : 0;
  s.movingRuns = debris_ && !debris_->atRest() ? 1 : 0;
  if (debris_ && debris_->unintendedFall()) {
    s.unintendedRuns = 1;
    s.verdict = fallVerdictName(debris_->verdict);
  }
  if (debris_) s.kineticRatio = debris_->kineticRatio;
  return s;
}

RunWatches::Saved RunWatches::saved() const {
  Saved s;
  s.hingeStep = hingeStep_;
  s.hingeCount = hingeCount_;
  s.maxMomentRatio = capacity_.maxRatio();
  s.peakGroundForce = peakGroundForce_;
  s.peakGroundTime = peakGroundTime_;
  s.peakKinetic = peakKinetic_;
  s.restRatio = restRatio_;
  s.lastMoving = lastMoving_;
  s.deepest = deepest_;
  s.deepestTime = deepestTime_;
  s.jointsFormed = topology_.jointsFormed;
  s.jointsRuptured = topology_.jointsRuptured;
  s.removed = removed_;
  s.hinges = topology_.hinges;
  s.fractures = topology_.fractures;
  s.shears = topology_.shears;
  s.dynamicSeen = dynamicSeen_;
  return s;
}

void RunWatches::restore(const Saved& s) {
  hingeStep_ = s.hingeStep;
  hingeCount_ = s.hingeCount;
  capacity_.setMaxRatio(s.maxMomentRatio);
  peakGroundForce_ = s.peakGroundForce;
  peakGroundTime_ = s.peakGroundTime;
  peakKinetic_ = s.peakKinetic;
  restRatio_ = s.restRatio;
  lastMoving_ = s.lastMoving;
  deepest_ = s.deepest;
  deepestTime_ = s.deepestTime;
  topology_.jointsFormed = s.jointsFormed;
  topology_.jointsRuptured = s.jointsRuptured;
  removed_ = s.removed;
  topology_.hinges = s.hinges;
  topology_.fractures = s.fractures;
  topology_.shears = s.shears;
  dynamicSeen_ = s.dynamicSeen;
}

}  // namespace c2d
