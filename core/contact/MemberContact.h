#pragma once
// Penalty contact between members (CONTact record MEMBers,,k[,zeta[,r[,mu[,e]]]]):
// every node against every element segment it does not belong to. The model,
// the invariants and the tests: docs/design/member-contact.md.
//
// This class coordinates its pieces for the assembler: the search and its near
// lists (core/contact/ContactSearch.h), the pairs' step starts
// (core/contact/PairStarts.h), the pair law (core/contact/MemberPairLaw.h) and
// the pairs' memory from step to step (core/contact/PairMemories.h). What they
// keep changes as the states they are asked about change: the methods that
// may change it are not const.
#include <vector>

#include "core/contact/ContactMotion.h"
#include "core/contact/ContactPair.h"
#include "core/contact/ContactSearch.h"
#include "core/contact/MemberPairLaw.h"
#include "core/contact/PairContact.h"
#include "core/contact/PairStarts.h"
#include "core/contact/StateStamp.h"
#include "core/DofMap.h"
#include "core/Model.h"
#include "core/State.h"
#include "core/StepRule.h"

namespace c2d {

class MemberContact {
 public:
  // Per topology version (ContactSearch's constructor).
  MemberContact(const Model& model, const DofMap& dofs);

  // ContactSearch::candidates.
  const std::vector<ContactPair>& candidates(const Model& model, const State& s) {
    return search_.candidates(model, s);
  }
  int candidatesVersion() const { return search_.version(); }

  // The candidates at s; those (indices, ascending) whose swept boxes over
  // the step to s may come within their contact distance plus extra (reach);
  // and of these the ones that may touch (near: all but the pairs that
  // neither touch at t_n nor can come to touch while the list holds,
  // core/contact/PairStarts.h mayTouch). evaluate() finds no force on a pair
  // of reach that is not near. Notes the step start of s.
  struct Nearby {
    const std::vector<ContactPair>& candidates;
    const std::vector<int>& reach;
    const std::vector<int>& near;
  };
  Nearby nearby(const Model& model, const State& s, double extra);

  // Force and tangent of the candidate pair `index` of the last nearby(), at
  // its state s (false: no force), with the pair's memory in s.pairs, from
  // its kept step start.
  bool evaluate(int index, const Model& model, const State& s, const StepRule& rule,
                bool wantTangent, PairVec& force, PairMat& tangent);
  // An assembly under `rule` is made (the rule the friction stretches of its
  // trial state belong to, as evaluate() notes it), its nearby() list of
  // pairs within reach empty or not (evaluate() notes the rule of every one).
  void assembling(const StepRule& rule, bool reached) {
    if (reached || lastRule_.scheme != rule.scheme || lastRule_.alpha != rule.alpha)
      lastRule_ = rule;
  }
  // The pair comes within extra of touching over the step to s: its
  // penetration, as evaluate() sees it, exceeds -extra at t_n or t_n+1.
  bool within(const ContactPair& pair, const Model& model, const State& s, double extra) const;
  // The pair's swept boxes at the last nearby() are within contact distance plus extra.
  bool sweptReach(const ContactPair& pair, double extra) const {
    return search_.sweptReach(pair, extra);
  }

  // Stored energy at the trial state s (sides and memory from its committed
  // state), and the energy the crushing and the dissipative term took over the
  // step from t_n to t_n+1.
  double energy(const Model& model, const State& s);
  double dissipation(const Model& model, const State& s, const StepRule& rule);
  // The motion over the step to s of every pair that touches at either end
  // (core/contact/ContactMotion.h), appended to out.
  void motions(const Model& model, const State& s, std::vector<ContactMotion>& out);

  // At a commit: the memory of every pair in contact at the end of the step
  // into s.pairs (core/contact/PairMemories.h). Returns the energy released
  // without work: a pair pushed past its segment's centre line (counted in
  // `pushed`, its energy added to `pushedEnergy`), a held pair let go, a
  // loading point moved to the peak of a turn inside the step.
  double commit(const Model& model, State& s, int& pushed, double& pushedEnergy);
  // The stored energy at the committed state s: as found by the last commit
  // (no pass over the pairs), or evaluated when none was made.
  double committedEnergy(const Model& model, const State& s) {
    return committed_ ? committedEnergy_ : energy(model, s);
  }
  // When the contact starts or the topology changes (s committed): the pairs
  // set free inside their contact distance start at zero force
  // (core/contact/PairMemories.h openPairs), and the reach of the memory is noted.
  void openPairs(const Model& model, State& s);

  double margin() const { return search_.margin(); }
  // The most a pair's memory reaches beyond its contact distance: evaluate()
  // sees a pair whose swept boxes are within its distance plus this.
  double slack() const { return slack_; }
  double radius(int element) const { return search_.radius(element); }

 private:
  // The step at s under the rule of the candidate `index` of the last
  // nearby(), and its penetration at the full contact distance (full).
  PairOutcome outcome(int index, const Model& model, const State& s, const StepRule& rule,
                      double* full);
  // outcome() of every pair touching() at s under rule: a commit reads them
  // three times at one state (energy(), dissipation(), commit()), so they are
  // found once and kept while the candidates, the state, the rule and the
  // slack are those they were found for.
  struct StepOutcome {
    int index = -1;  // the pair's in the candidates
    PairOutcome outcome;
    double full = 0;
  };
  const std::vector<StepOutcome>& outcomes(const Model& model, const State& s,
                                           const StepRule& rule);
  // The candidates a commit's passes visit: those of the near list within
  // reach plus the slack, and those with a memory (ContactSearch::touching).
  const std::vector<int>& touching(const Model& model, const State& s);

  ContactSearch search_;
  PairStarts starts_;
  MemberPairLaw law_;
  double slack_ = 0;  // the most a pair's memory reaches beyond its distance
  // The rule of the last evaluation: the friction springs' stretches at a
  // trial state are those of the step that was assembled (as the ground's).
  StepRule lastRule_;
  // outcomes() and what they were found for.
  std::vector<StepOutcome> outcomes_;
  bool outcomesValid_ = false;
  int outcomesVersion_ = -1;
  StepRule outcomesRule_;
  double outcomesSlack_ = 0;
  StateStamp outcomesState_;
  std::vector<PairMemory> nextMemory_;  // commit()'s and openPairs()' scratch
  double committedEnergy_ = 0;
  bool committed_ = false;  // committedEnergy_ is that of a commit
};

}  // namespace c2d
