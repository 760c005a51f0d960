#pragma once
// The member contact's law on one pair (docs/design/member-contact.md): the
// pair's PairLaw (core/contact/PairContact.h) from the MEMBers record, its
// memory and the nodes' masses, and what the law gives over a step from the
// pair's kept start (core/contact/PairStarts.h): force and tangent, outcome,
// stored and dissipated energy, the motion the impacts' step control sees.
#include <utility>
#include <vector>

#include "core/contact/ContactMotion.h"
#include "core/contact/ContactPair.h"
#include "core/contact/PairContact.h"
#include "core/contact/PairStarts.h"
#include "core/Model.h"
#include "core/State.h"
#include "core/StepRule.h"

namespace c2d {

class MemberPairLaw {
 public:
  // masses: per node (core/NodeMass.h).
  MemberPairLaw(const MemberContactData& data, std::vector<double> masses)
      : data_(data), masses_(std::move(masses)) {}
  const MemberContactData& data() const { return data_; }
  const std::vector<double>& masses() const { return masses_; }

  // The pair's law at s with the memory m (its dashpot for the masses at t_n: q0).
  PairLaw law(const ContactPair& pair, const State& s, const PairPositions& q0,
              const PairMemory* m) const;
  // The start's law and mass, formed at the first call: most candidates are
  // apart, and their law (the dashpot's pair mass and rates) is never needed.
  void form(PairStart& start, const ContactPair& pair, const State& s) const;

  // Force and tangent of the pair at the positions q1 (t_n+1) from its start
  // (false: no force).
  bool force(PairStart& start, const ContactPair& pair, const State& s, const PairPositions& q1,
             const StepRule& rule, bool wantTangent, PairVec& force, PairMat& tangent) const;
  // What the step from q0 to q1 (the pair's swept boxes within reach) did to
  // the pair, and its penetration at the full contact distance, without
  // offset, at t_n+1 (full).
  PairOutcome outcome(PairStart& start, const ContactPair& pair, const State& s,
                      const PairPositions& q0, const PairPositions& q1, const StepRule& rule,
                      double* full) const;
  // The outcome of a pair apart over the step: its friction spring lets go.
  PairOutcome apart(const PairMemory* m) const;
  // The energy the pair stores after its step.
  double energy(const PairMemory* m, const PairOutcome& o) const;
  // Adds to d what the pair's step dissipated: crushing, the dashpot (when
  // start is given: the pair's swept boxes within reach under the mid-point
  // scheme) and slipping.
  void dissipated(double& d, const PairMemory* m, const PairOutcome& o, PairStart* start,
                  const ContactPair& pair, const State& s, const StepRule& rule) const;
  // The pair's motion over the step from q0 to q1 (core/contact/ContactMotion.h);
  // false when it touches at neither end.
  bool motion(PairStart& start, const ContactPair& pair, const State& s, const PairPositions& q0,
              const PairPositions& q1, ContactMotion& out) const;

 private:
  MemberContactData data_;
  std::vector<double> masses_;
};

}  // namespace c2d
