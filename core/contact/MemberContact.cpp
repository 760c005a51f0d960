#include "core/contact/MemberContact.h"

#include <cmath>

#include "core/contact/PairMemories.h"
#include "core/contact/PairMotion.h"
#include "core/contact/SweptBoxes.h"
#include "core/NodeMass.h"

namespace c2d {

MemberContact::MemberContact(const Model& model, const DofMap& dofs)
    : search_(model, dofs, model.memberContact()->radius),
      law_(*model.memberContact(), translationalMasses(model)) {}

MemberContact::Nearby MemberContact::nearby(const Model& model, const State& s, double extra) {
  const std::vector<ContactPair>& candidates = search_.candidates(model, s);
  starts_.begin(s, search_.version(), candidates);
  const double slack = 0.25 * search_.margin();
  const std::vector<int>& reach = search_.reach(s, extra, slack);
  // A list found afresh at s: of its pairs, those that may touch while it
  // holds (each node within sqrt(2) SweptBoxes::holds of its place at s).
  const double move = std::sqrt(2.0) * SweptBoxes::holds(slack);
  const std::vector<int>& near = search_.near(reach, starts_.version(), [&](int i) {
    return mayTouch(starts_.of(i, candidates[i], model, s), candidates[i], model, s, move);
  });
  return {candidates, reach, near};
}

bool MemberContact::evaluate(int index, const Model& model, const State& s, const StepRule& rule,
                             bool wantTangent, PairVec& force, PairMat& tangent) {
  lastRule_ = rule;
  const ContactPair& pair = search_.candidates()[index];
  // The memory only of a pair within reach (slack_: the most a memory's
  // contact distance exceeds its pair's present one); the swept boxes'
  // test is pairPositions()'s.
  if (!search_.sweptReach(pair, slack_)) return false;
  PairStart& start = starts_.of(index, pair, model, s);
  const PairPositions q1{nodePosition(model, s.u, pair.node), nodePosition(model, s.u, pair.a),
                         nodePosition(model, s.u, pair.b)};
  return law_.force(start, pair, s, q1, rule, wantTangent, force, tangent);
}

bool MemberContact::within(const ContactPair& pair, const Model& model, const State& s,
                           double extra) const {
  PairPositions q0, q1;
  if (!pairPositions(pair, model, s, q0, q1, slack_ + extra)) return false;
  const PairMemory* m = pairMemory(s, pair.key());
  const int sd = heldSide(m, q0);
  const double h = pairReach(pair, m);
  return pairPenetration(q1, sd, h, endFaces(m)) > -extra ||
         pairPenetration(q0, sd, h, endFaces(m)) > -extra;
}

PairOutcome MemberContact::outcome(int index, const Model& model, const State& s,
                                   const StepRule& rule, double* full) {
  const ContactPair& pair = search_.candidates()[index];
  PairPositions q0, q1;
  if (!pairPositions(pair, model, s, q0, q1, slack_)) {  // apart: a friction spring lets go
    if (full) *full = 0;
    return law_.apart(pairMemory(s, pair.key()));
  }
  return law_.outcome(starts_.of(index, pair, model, s), pair, s, q0, q1, rule, full);
}

const std::vector<MemberContact::StepOutcome>& MemberContact::outcomes(const Model& model,
                                                                       const State& s,
                                                                       const StepRule& rule) {
  const std::vector<ContactPair>& candidates = search_.candidates(model, s);
  // Every input kept is compared: no caller has to say when the state changed.
  const bool sameState = outcomesState_.same(s, true);
  if (sameState && outcomesValid_ && outcomesVersion_ == search_.version() &&
      outcomesRule_ == rule && outcomesSlack_ == slack_)
    return outcomes_;
  // With the room of the candidates: steps allocate nothing while the
  // contacts change little.
  if (outcomes_.capacity() < candidates.capacity()) outcomes_.reserve(candidates.capacity());
  outcomesVersion_ = search_.version();
  outcomesRule_ = rule;
  outcomesSlack_ = slack_;
  outcomes_.clear();
  for (int i : touching(model, s)) {
    StepOutcome& o = outcomes_.emplace_back();
    o.index = i;
    o.outcome = outcome(i, model, s, rule, &o.full);
  }
  outcomesValid_ = true;
  return outcomes_;
}

const std::vector<int>& MemberContact::touching(const Model& model, const State& s) {
  const Nearby found = nearby(model, s, slack_);
  return search_.touching(found.near, s.pairs, slack_);
}

double MemberContact::energy(const Model& model, const State& s) {
  double w = 0;
  const std::vector<StepOutcome>& found = outcomes(model, s, lastRule_);
  const std::vector<ContactPair>& pairs = search_.candidates();  // as outcomes() found them
  for (const StepOutcome& f : found)
    w += law_.energy(pairMemory(s, pairs[f.index].key()), f.outcome);
  return w;
}

double MemberContact::dissipation(const Model& model, const State& s, const StepRule& rule) {
  const MemberContactData& data = law_.data();
  const bool damped = data.zeta > 0 && rule.scheme == Scheme::MidPoint;
  const bool crushes = data.restitution < 1;
  if (!damped && !crushes && data.mu <= 0) return 0;
  double d = 0;
  PairPositions q0, q1;
  const std::vector<StepOutcome>& found = outcomes(model, s, rule);
  const std::vector<ContactPair>& pairs = search_.candidates();  // as outcomes() found them
  for (const StepOutcome& f : found) {
    const ContactPair& pair = pairs[f.index];
    // The dashpot's share from the pair's kept law, when within reach.
    PairStart* start = damped && pairPositions(pair, model, s, q0, q1, slack_)
                           ? &starts_.of(f.index, pair, model, s)
                           : nullptr;
    law_.dissipated(d, pairMemory(s, pair.key()), f.outcome, start, pair, s, rule);
  }
  return d;
}

void MemberContact::motions(const Model& model, const State& s, std::vector<ContactMotion>& out) {
  PairPositions q0, q1;
  const std::vector<int>& visit = touching(model, s);
  const std::vector<ContactPair>& pairs = search_.candidates();  // as touching() found them
  ContactMotion motion;
  for (int i : visit) {
    const ContactPair& pair = pairs[i];
    if (!pairPositions(pair, model, s, q0, q1, slack_)) continue;
    if (law_.motion(starts_.of(i, pair, model, s), pair, s, q0, q1, motion)) out.push_back(motion);
  }
}

double MemberContact::commit(const Model& model, State& s, int& pushed, double& pushedEnergy) {
  const std::vector<StepOutcome>& found = outcomes(model, s, lastRule_);
  const std::vector<ContactPair>& pairs = search_.candidates();  // as outcomes() found them
  nextMemory_.clear();
  if (nextMemory_.capacity() < pairs.size()) nextMemory_.reserve(2 * pairs.size());
  CommitTally tally;
  PairPositions q0, q1;
  PairMemory next;
  for (const StepOutcome& f : found) {
    const ContactPair& pair = pairs[f.index];
    const bool near = pairPositions(pair, model, s, q0, q1, slack_);
    if (commitPair(law_, pair, s, pairMemory(s, pair.key()), f.outcome, f.full, near, q0, q1,
                   slack_, tally, next))
      nextMemory_.push_back(next);
  }
  // Candidates are sorted by key, so is the memory. Copied, with room to
  // double, so that steps allocate nothing while the contacts change little.
  if (s.pairs.capacity() < nextMemory_.size()) s.pairs.reserve(2 * nextMemory_.size());
  s.pairs.assign(nextMemory_.begin(), nextMemory_.end());
  committedEnergy_ = tally.stored;
  committed_ = true;
  pushed += tally.pushed;
  pushedEnergy += tally.released;
  return tally.released + tally.letGo + tally.crushed;
}

void MemberContact::openPairs(const Model& model, State& s) {
  slack_ = memorySlack(search_, model, s.pairs);
  c2d::openPairs(search_, model, s, nextMemory_);
}

}  // namespace c2d
