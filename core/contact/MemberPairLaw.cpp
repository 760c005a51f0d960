#include "core/contact/MemberPairLaw.h"

#include <algorithm>

#include "core/contact/ContactDamper.h"
#include "core/contact/CrushingLaw.h"
#include "core/contact/PairMotion.h"
#include "core/contact/SpringFriction.h"

namespace c2d {

PairLaw MemberPairLaw::law(const ContactPair& pair, const State& s, const PairPositions& q0,
                           const PairMemory* m) const {
  PairLaw out{data_.k, 0.0, data_.restitution, m ? m->q : 0.0, data_.mu, m ? m->stretch : 0.0};
  if (data_.mu > 0) out.stick = frictionStickDamping(data_.k, pairMass(masses_, pair, q0));
  if (data_.zeta > 0) {
    out.c = damperCoefficient(data_.zeta, data_.k, pairMass(masses_, pair, q0));
    out.zv = pairZ(pairValues(s.vn, pair));
    out.za = pairZ(pairValues(s.an, pair));
  }
  return out;
}

void MemberPairLaw::form(PairStart& start, const ContactPair& pair, const State& s) const {
  if (start.lawFound) return;
  start.law = law(pair, s, start.q0, start.remembers());
  start.mass = pairMass(masses_, pair, start.q0);
  start.lawFound = true;
}

bool MemberPairLaw::force(PairStart& start, const ContactPair& pair, const State& s,
                          const PairPositions& q1, const StepRule& rule, bool wantTangent,
                          PairVec& force, PairMat& tangent) const {
  PairStep step;
  step.z0 = start.z0;
  step.p0 = start.p0;
  if (!pairTouches(q1, start.side, start.reach, rule, wantTangent, step, start.face)) return false;
  form(start, pair, s);
  pairContact(step, start.side, start.reach, start.law, rule, wantTangent, force, tangent, nullptr,
              start.face);
  return true;
}

PairOutcome MemberPairLaw::outcome(PairStart& start, const ContactPair& pair, const State& s,
                                   const PairPositions& q0, const PairPositions& q1,
                                   const StepRule& rule, double* full) const {
  const PairMemory* m = start.remembers();
  const int sd = start.side;
  if (full) *full = pairPenetration(q1, sd, contactDistance(pair, m), start.face);
  PairOutcome out;
  if (q0.x == q1.x && q0.a == q1.a && q0.b == q1.b) {
    // No step (the committed state itself): nothing slides or lets go; the
    // energy is that of the memory (so that the account sees no jump where a
    // commit in place or a topology change evaluates it).
    out.p0 = out.p1 = pairPenetration(q1, sd, start.reach, start.face);
    out.stretch = m ? m->stretch : 0.0;
    return out;
  }
  PairStep step;
  step.z0 = start.z0;
  step.p0 = start.p0;
  const bool touching = pairTouches(q1, sd, start.reach, rule, false, step, start.face);
  out.p0 = step.p0;
  out.p1 = step.p1;
  if (data_.mu <= 0) return out;  // frictionless: the penetrations tell all
  if (!touching) {
    // Apart over the step (as pairContact decides): the friction spring lets
    // go, and the law is not formed.
    out.slipped = springFrictionEnergy(data_.k, m ? m->stretch : 0.0);
    return out;
  }
  PairVec f;
  PairMat k;
  form(start, pair, s);
  pairContact(step, sd, start.reach, start.law, rule, false, f, k, &out, start.face);
  return out;
}

PairOutcome MemberPairLaw::apart(const PairMemory* m) const {
  PairOutcome out;
  if (m) out.slipped = springFrictionEnergy(data_.k, m->stretch);
  return out;
}

double MemberPairLaw::energy(const PairMemory* m, const PairOutcome& o) const {
  return crushingEnergy(data_.k, data_.restitution, m ? m->q : 0.0, o.p1) +
         springFrictionEnergy(data_.k, o.stretch);
}

void MemberPairLaw::dissipated(double& d, const PairMemory* m, const PairOutcome& o,
                               PairStart* start, const ContactPair& pair, const State& s,
                               const StepRule& rule) const {
  const double q = m ? m->q : 0.0;
  if (data_.restitution < 1) d += CrushingLaw(data_.k, data_.restitution, q).dissipated(o.p0, o.p1);
  if (start) {
    form(*start, pair, s);
    d += damperDissipation(start->law.c,
                           CrushingLaw(data_.k, data_.restitution, std::max(q, o.p0)).ps, o.p0,
                           o.p1, rule);
  }
  d += o.slipped;
}

bool MemberPairLaw::motion(PairStart& start, const ContactPair& pair, const State& s,
                           const PairPositions& q0, const PairPositions& q1,
                           ContactMotion& out) const {
  const int sd = start.side;
  const double h = start.reach, f = start.face;
  const double p0 = start.p0, p1 = pairPenetration(q1, sd, h, f);
  if (p0 <= 0 && p1 <= 0) return false;
  form(start, pair, s);
  const PairLaw& l = start.law;
  out = {p0, p1, pairPenetrationRate(q0, pairValues(s.vn, pair), sd, h, f),
         pairPenetrationRate(q1, pairValues(s.v, pair), sd, h, f), l.k, l.restitution,
         l.q, l.c, start.mass};
  return true;
}

}  // namespace c2d
