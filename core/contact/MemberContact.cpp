#include "core/contact/MemberContact.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>

#include "core/Brace.h"
#include "core/contact/ContactDamper.h"
#include "core/contact/CrushingLaw.h"
#include "core/NodeMass.h"
#include "core/contact/PairMotion.h"
#include "core/contact/SpringFriction.h"

namespace c2d {

namespace {

// Held sides (the pairs of a ruptured joint), as fractions of the contact
// distance: a node this close to a segment is on it, a member whose far end
// is this close to the segment's line lies along it, and a held node this far
// clear of the line (or around the end) is let go.
constexpr double kOnSegment = 1e-6, kAlongLine = 1e-3, kLetGo = 0.25;

// Joint groups merged further with the nodes at one reference position: the
// nodes of the original mesh (a joint that ruptured still joins its two nodes
// here).
std::vector<int> originalGroups(const Model& model, const std::vector<int>& groups) {
  const int nn = model.numNodes();
  std::vector<int> parent = groups, order(nn);
  auto find = [&](int n) {
    while (parent[n] != n) n = parent[n] = parent[parent[n]];
    return n;
  };
  std::iota(order.begin(), order.end(), 0);
  auto less = [&](int a, int b) {
    const Vec2 &x = model.coord(a), &y = model.coord(b);
    return x.x() < y.x() || (x.x() == y.x() && x.y() < y.y());
  };
  std::sort(order.begin(), order.end(), less);
  for (int i = 1; i < nn; ++i)
    if (!less(order[i - 1], order[i])) {
      const int a = find(order[i - 1]), b = find(order[i]);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  for (int n = 0; n < nn; ++n) parent[n] = find(n);
  return parent;
}

// The node groups joined by the live elements.
class GroupGraph {
 public:
  GroupGraph(const Model& model, const std::vector<int>& live, std::vector<int> group)
      : model_(model), group_(std::move(group)), start_(group_.size() + 1, 0) {
    for (int e : live)
      for (int n : model.element(e).nodes()) ++start_[group_[n] + 1];
    for (std::size_t g = 1; g < start_.size(); ++g) start_[g] += start_[g - 1];
    elements_.resize(start_.back());
    std::vector<int> fill(start_.begin(), start_.end() - 1);
    for (int e : live)
      for (int n : model.element(e).nodes()) elements_[fill[group_[n]]++] = e;
  }
  // Elements on the shortest path from node n's group to a node of element e
  // (0: e has a node in it), counted up to maxHops; beyond: maxHops + 1.
  int hops(int n, int e, int maxHops) const {
    const auto target = model_.element(e).nodes();
    std::vector<int> frontier{group_[n]}, seen{group_[n]}, next;
    for (int depth = 0; depth <= maxHops; ++depth) {
      for (int g : frontier)
        if (g == group_[target[0]] || g == group_[target[1]]) return depth;
      next.clear();
      for (int g : frontier)
        for (int i = start_[g]; i < start_[g + 1]; ++i)
          for (int m : model_.element(elements_[i]).nodes())
            if (std::find(seen.begin(), seen.end(), group_[m]) == seen.end()) {
              seen.push_back(group_[m]);
              next.push_back(group_[m]);
            }
      frontier.swap(next);
    }
    return maxHops + 1;
  }

 private:
  const Model& model_;
  std::vector<int> group_;
  std::vector<int> start_, elements_;
};

}  // namespace

double sectionRadius(const Model& model, int element) {
  const MaterialSet* m = model.material(model.element(element).materialNumber());
  return m && m->A > 0 && m->I > 0 ? std::sqrt(3 * m->I / m->A) : 0.0;
}

std::vector<int> jointGroups(const Model& model) {
  std::vector<int> parent(model.numNodes());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int n) {
    while (parent[n] != n) n = parent[n] = parent[parent[n]];
    return n;
  };
  for (const Joint& j : model.joints()) {
    const int a = find(j.master), b = find(j.slave);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
  for (int n = 0; n < model.numNodes(); ++n) parent[n] = find(n);
  return parent;
}

// ---------------------------------------------------------------------------

MemberContact::MemberContact(const Model& model, const DofMap& dofs)
    : data_(*model.memberContact()) {
  const int nn = model.numNodes();
  for (int e = 0; e < model.numElements(); ++e)
    if (model.hasElement(e) && !isBrace(model.element(e))) live_.push_back(e);  // struts strike nothing
  const int ne = static_cast<int>(live_.size());
  group_ = jointGroups(model);
  masses_ = translationalMasses(model);
  usedNode_.assign(nn, 0);
  for (int n = 0; n < nn; ++n) {
    if (!dofs.used(n)) continue;
    usedNode_[n] = 1;
    if (!dofs.aliased(n)) contactNodes_.push_back(n);
  }
  const double shortest = model.characteristicLength();
  const double fallback = data_.radius >= 0 ? data_.radius : 1e-3 * shortest;
  elementRadius_.assign(model.numElements(), fallback);
  nodeRadius_.assign(nn, 0.0);
  double length = 0;
  for (int e : live_) {
    const Element& el = model.element(e);
    if (const double r = sectionRadius(model, e); r > 0) elementRadius_[e] = r;
    const auto nodes = el.nodes();
    length += (model.coord(nodes[0]) - model.coord(nodes[1])).norm();
    for (int n : nodes) nodeRadius_[n] = std::max(nodeRadius_[n], elementRadius_[e]);
  }
  // A node's contact radius is that of its joint group.
  for (int n = 0; n < nn; ++n)
    nodeRadius_[group_[n]] = std::max(nodeRadius_[group_[n]], nodeRadius_[n]);
  for (int n = 0; n < nn; ++n) nodeRadius_[n] = nodeRadius_[group_[n]];
  // The margin of the candidate search: half the mean element length.
  margin_ = ne > 0 ? 0.5 * length / ne : 1.0;

  // Pairs within contact distance in the reference configuration.
  std::vector<Box> boxes(ne);
  for (int i = 0; i < ne; ++i) {
    const int e = live_[i];
    const auto nodes = model.element(e).nodes();
    Box b = Box::point(model.coord(nodes[0]).x(), model.coord(nodes[0]).y());
    b.add(model.coord(nodes[1]).x(), model.coord(nodes[1]).y());
    boxes[i] = b.inflated(elementRadius_[e]);
  }
  // Such a pair stays excluded while the members between them hold: while the
  // node is as few elements from the segment as in the original mesh (joints
  // that ruptured since are counted as broken), or when it was not within a
  // few elements of it there.
  ContactGrid grid;
  grid.build(boxes, 1e-6 * shortest);
  const GroupGraph now(model, live_, group_), original(model, live_, originalGroups(model, group_));
  constexpr int kNearHops = 3;
  for (int n : contactNodes_) {
    const Vec2& x = model.coord(n);
    grid.query(Box::point(x.x(), x.y()).inflated(nodeRadius_[n]), [&](int i) {
      const int e = live_[i];
      if (excluded(n, e, model)) return;
      const auto nodes = model.element(e).nodes();
      const PairPositions q{x, model.coord(nodes[0]), model.coord(nodes[1])};
      const double h = nodeRadius_[n] + elementRadius_[e];
      // Without a side: the distance itself (p = h - |d| inside the span).
      if (pairPenetration(q, pairSide(q), h) <= 0) return;
      const int was = original.hops(n, e, kNearHops);
      if (was > kNearHops || now.hops(n, e, was) <= was)
        referenceExcluded_.push_back(ContactPair{n, e}.key());
    });
  }
  std::sort(referenceExcluded_.begin(), referenceExcluded_.end());
  anchor_.resize(nn);
}

bool MemberContact::excluded(int node, int element, const Model& model) const {
  for (int m : model.element(element).nodes())
    if (group_[m] == group_[node]) return true;
  return false;
}

namespace {

// Assigns b to a and tells whether they were the same already, to the bit
// (what decides that a result found from a still holds; memcmp, not ==: the
// comparison runs at every assembly).
bool keep(Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  if (a.size() == b.size() &&
      (b.size() == 0 ||
       std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(b.size())) == 0))
    return true;
  a = b;
  return false;
}

}  // namespace

bool MemberContact::valid() const {
  if (!searched_) return false;
  for (int n = 0; n < static_cast<int>(usedNode_.size()); ++n) {
    if (!usedNode_[n]) continue;
    const Box& a = anchor_[n];
    const Box& b = swept_.box(n);
    if (b.x0 < a.x0 - margin_ || b.x1 > a.x1 + margin_ || b.y0 < a.y0 - margin_ ||
        b.y1 > a.y1 + margin_)
      return false;
  }
  return true;
}

MemberContact::Nearby MemberContact::nearby(const Model& model, const State& s,
                                            double extra) const {
  candidates(model, s);
  // Every input compared (and copied when it differs).
  bool same = startCandidates_ == candidatesVersion_;
  same = keep(startUn_, s.un) && same;
  same = keep(startVn_, s.vn) && same;
  same = keep(startAn_, s.an) && same;
  if (!same || startPairs_ != s.pairs) {
    ++startVersion_;
    startCandidates_ = candidatesVersion_;
    if (startPairs_.capacity() < s.pairs.capacity()) startPairs_.reserve(s.pairs.capacity());
    startPairs_.assign(s.pairs.begin(), s.pairs.end());
    if (start_.size() < candidates_.size()) start_.resize(candidates_.capacity());
  }
  const double slack = 0.25 * margin_;
  const std::vector<int>& reach = swept_.near(s, candidates_, candidatesVersion_, extra, slack);
  if (swept_.listVersion() != nearList_) {
    // Found afresh at s: of its pairs, those that may touch while it holds
    // (each node within sqrt(2) SweptBoxes::holds of its place at s). Most
    // of the pairs within reach by their boxes are members lying along each
    // other (the main example with member contact, per assembly over the
    // run: 341 within reach, 141 that may touch, 48 touching).
    near_.clear();
    if (near_.capacity() < reach.capacity()) near_.reserve(reach.capacity());  // none in a step
    const double move = std::sqrt(2.0) * SweptBoxes::holds(slack);
    for (int i : reach)
      if (mayTouch(i, model, s, move)) near_.push_back(i);
    nearList_ = swept_.listVersion();
    nearStart_ = startVersion_;
  }
  // A step start found anew under a kept list: every pair within reach.
  return {candidates_, reach, nearStart_ == startVersion_ ? near_ : reach};
}

bool MemberContact::mayTouch(int index, const Model& model, const State& s, double move) const {
  const PairStart& start = startOf(index, model, s);
  if (start.remembered || start.p0 > 0) return true;
  const ContactPair& pair = candidates_[index];
  const Vec2 r1 = nodePosition(model, s.u, pair.node) - nodePosition(model, s.u, pair.a);
  const Vec2 r2 = nodePosition(model, s.u, pair.b) - nodePosition(model, s.u, pair.a);
  const double l2 = r2.squaredNorm(), h = start.reach;
  if (!(l2 > 16 * move * move) || !(h > 2.5 * move)) return true;
  const double d = start.side * (r2.x() * r1.y() - r2.y() * r1.x());  // on its side: > 0
  const double xi = std::clamp(r1.dot(r2) / l2, 0.0, 1.0);
  const double dist = (r1 - xi * r2).norm();
  return !(d > 0 && dist > h + 2.5 * move);
}

void MemberContact::search(const Model& model) const {
  const int ne = static_cast<int>(live_.size());
  // The nodes' swept boxes at s (candidates() has just formed them).
  for (int n = 0; n < model.numNodes(); ++n)
    if (usedNode_[n]) anchor_[n] = swept_.box(n);
  boxes_.resize(ne);
  for (int i = 0; i < ne; ++i) {
    const int e = live_[i];
    const auto nodes = model.element(e).nodes();
    Box b = anchor_[nodes[0]];
    b.add(anchor_[nodes[1]].x0, anchor_[nodes[1]].y0);
    b.add(anchor_[nodes[1]].x1, anchor_[nodes[1]].y1);
    boxes_[i] = b.inflated(elementRadius_[e] + margin_);
  }
  grid_.build(boxes_, 1e-6 * margin_);
  candidates_.clear();
  for (int n : contactNodes_) {
    grid_.query(anchor_[n].inflated(nodeRadius_[n] + margin_), [&](int i) {
      const int e = live_[i];
      if (excluded(n, e, model)) return;
      const ContactPair key{n, e};
      if (std::binary_search(referenceExcluded_.begin(), referenceExcluded_.end(), key.key()))
        return;
      const auto nodes = model.element(e).nodes();
      candidates_.push_back({n, e, nodes[0], nodes[1], nodeRadius_[n] + elementRadius_[e]});
    });
  }
  std::sort(candidates_.begin(), candidates_.end(),
            [](const ContactPair& p, const ContactPair& q) { return p.key() < q.key(); });
  // Room for the list to double before a later search must allocate (steps
  // allocate nothing while the contacts change little).
  if (candidates_.capacity() < 2 * candidates_.size()) candidates_.reserve(2 * candidates_.size());
  searched_ = true;
  ++candidatesVersion_;
}

const std::vector<ContactPair>& MemberContact::candidates(const Model& model,
                                                          const State& s) const {
  swept_.update(model, s);
  if (!valid()) search(model);
  return candidates_;
}


const PairMemory* MemberContact::memory(const State& s, std::uint64_t key) {
  const auto it = std::lower_bound(s.pairs.begin(), s.pairs.end(), key,
                                   [](const PairMemory& m, std::uint64_t k) { return m.key < k; });
  return it != s.pairs.end() && it->key == key ? &*it : nullptr;
}

MemberContact::PairStart& MemberContact::startOf(int index, const Model& model,
                                                 const State& s) const {
  PairStart& start = start_[index];
  if (start.version == startVersion_) return start;
  const ContactPair& pair = candidates_[index];
  start.version = startVersion_;
  const PairMemory* m = memory(s, pair.key());
  start.remembered = m != nullptr;
  if (m) start.memory = *m;
  start.q0 = {nodePosition(model, s.un, pair.node), nodePosition(model, s.un, pair.a),
              nodePosition(model, s.un, pair.b)};
  start.side = side(m, start.q0);
  start.reach = reach(pair, m);
  start.face = face(m);
  PairStep step;
  pairStart(start.q0, start.side, start.reach, step, start.face);
  start.z0 = step.z0;
  start.p0 = step.p0;
  start.lawFound = false;
  return start;
}

void MemberContact::formLaw(PairStart& start, const ContactPair& pair, const State& s) const {
  if (start.lawFound) return;
  start.law = law(pair, s, start.q0, start.remembered ? &start.memory : nullptr);
  start.mass = pairMass(masses_, pair, start.q0);
  start.lawFound = true;
}

bool MemberContact::evaluate(int index, const Model& model, const State& s, const StepRule& rule,
                             bool wantTangent, PairVec& force, PairMat& tangent) const {
  lastRule_ = rule;
  const ContactPair& pair = candidates_[index];
  // The memory only of a pair within reach (slack_: the most a memory's
  // contact distance exceeds its pair's present one); the swept boxes'
  // test is positions()'s.
  if (!swept_.reach(pair, slack_)) return false;
  PairStart& start = startOf(index, model, s);
  PairStep step;
  step.z0 = start.z0;
  step.p0 = start.p0;
  const PairPositions q1{nodePosition(model, s.u, pair.node), nodePosition(model, s.u, pair.a),
                         nodePosition(model, s.u, pair.b)};
  if (!pairTouches(q1, start.side, start.reach, rule, wantTangent, step, start.face)) return false;
  // Most candidates are apart (a twelfth carries a force): their law (the
  // dashpot's pair mass and rates) is formed once one touches.
  formLaw(start, pair, s);
  pairContact(step, start.side, start.reach, start.law, rule, wantTangent, force, tangent, nullptr,
              start.face);
  return true;
}

bool MemberContact::within(const ContactPair& pair, const Model& model, const State& s,
                           double extra) const {
  PairPositions q0, q1;
  if (!positions(pair, model, s, q0, q1, slack_ + extra)) return false;
  const PairMemory* m = memory(s, pair.key());
  const int sd = side(m, q0);
  const double h = reach(pair, m);
  return pairPenetration(q1, sd, h, face(m)) > -extra ||
         pairPenetration(q0, sd, h, face(m)) > -extra;
}

PairOutcome MemberContact::outcome(int index, const Model& model, const State& s,
                                   const StepRule& rule, double* full) const {
  const ContactPair& pair = candidates_[index];
  PairPositions q0, q1;
  if (!positions(pair, model, s, q0, q1, slack_)) {  // apart: a friction spring lets go
    const PairMemory* m = memory(s, pair.key());
    if (full) *full = 0;
    PairOutcome out;
    if (m) out.slipped = springFrictionEnergy(data_.k, m->stretch);
    return out;
  }
  PairStart& start = startOf(index, model, s);
  const PairMemory* m = start.remembered ? &start.memory : nullptr;
  const int sd = start.side;
  if (full) *full = pairPenetration(q1, sd, distance(pair, m), start.face);
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
  formLaw(start, pair, s);
  pairContact(step, sd, start.reach, start.law, rule, false, f, k, &out, start.face);
  return out;
}

const std::vector<MemberContact::StepOutcome>& MemberContact::outcomes(const Model& model,
                                                                       const State& s,
                                                                       const StepRule& rule) const {
  candidates(model, s);  // their version, compared below
  // Every input kept is compared (and copied when it differs): no caller has
  // to say when the state changed.
  bool same = outcomesValid_ && outcomesVersion_ == candidatesVersion_ &&
              outcomesRule_ == rule && outcomesSlack_ == slack_;
  same = keep(outcomesU_, s.u) && same;
  same = keep(outcomesUn_, s.un) && same;
  same = keep(outcomesVn_, s.vn) && same;
  same = keep(outcomesAn_, s.an) && same;
  if (same && outcomesPairs_ == s.pairs) return outcomes_;
  // With the room of the memory and of the candidates: steps allocate nothing
  // while the contacts change little.
  if (outcomesPairs_.capacity() < s.pairs.capacity()) outcomesPairs_.reserve(s.pairs.capacity());
  outcomesPairs_.assign(s.pairs.begin(), s.pairs.end());
  if (outcomes_.capacity() < candidates_.capacity()) outcomes_.reserve(candidates_.capacity());
  outcomesVersion_ = candidatesVersion_;
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

const std::vector<int>& MemberContact::touching(const Model& model, const State& s) const {
  const Nearby found = nearby(model, s, slack_);
  const std::vector<ContactPair>& pairs = found.candidates;
  touching_.clear();
  if (touching_.capacity() < pairs.capacity()) touching_.reserve(pairs.capacity());
  for (int i : found.near)
    if (swept_.reach(pairs[i], slack_)) touching_.push_back(i);
  // The pairs in memory out of reach (a friction spring or a held side let
  // go), in key order as the candidates are.
  const auto within = static_cast<std::ptrdiff_t>(touching_.size());
  for (const PairMemory& m : s.pairs) {
    const auto it = std::lower_bound(pairs.begin(), pairs.end(), m.key,
                                     [](const ContactPair& p, std::uint64_t k) { return p.key() < k; });
    if (it != pairs.end() && it->key() == m.key && !swept_.reach(*it, slack_))
      touching_.push_back(static_cast<int>(it - pairs.begin()));
  }
  std::inplace_merge(touching_.begin(), touching_.begin() + within, touching_.end());
  return touching_;
}

double MemberContact::energy(const Model& model, const State& s) const {
  double w = 0;
  const std::vector<StepOutcome>& found = outcomes(model, s, lastRule_);
  const std::vector<ContactPair>& pairs = candidates_;  // as outcomes() found them
  for (const StepOutcome& f : found) {
    const PairMemory* m = memory(s, pairs[f.index].key());
    const PairOutcome& o = f.outcome;
    w += crushingEnergy(data_.k, data_.restitution, m ? m->q : 0.0, o.p1) +
         springFrictionEnergy(data_.k, o.stretch);
  }
  return w;
}

double MemberContact::dissipation(const Model& model, const State& s, const StepRule& rule) const {
  const bool damped = data_.zeta > 0 && rule.scheme == Scheme::MidPoint;
  const bool crushes = data_.restitution < 1;
  if (!damped && !crushes && data_.mu <= 0) return 0;
  double d = 0;
  PairPositions q0, q1;
  const std::vector<StepOutcome>& found = outcomes(model, s, rule);
  const std::vector<ContactPair>& pairs = candidates_;  // as outcomes() found them
  for (const StepOutcome& f : found) {
    const ContactPair& pair = pairs[f.index];
    const PairMemory* m = memory(s, pair.key());
    const PairOutcome& o = f.outcome;
    const double q = m ? m->q : 0.0;
    if (crushes) d += CrushingLaw(data_.k, data_.restitution, q).dissipated(o.p0, o.p1);
    if (damped && positions(pair, model, s, q0, q1, slack_)) {
      PairStart& start = startOf(f.index, model, s);
      formLaw(start, pair, s);
      d += damperDissipation(start.law.c,
                             CrushingLaw(data_.k, data_.restitution, std::max(q, o.p0)).ps, o.p0,
                             o.p1, rule);
    }
    d += o.slipped;
  }
  return d;
}

void MemberContact::motions(const Model& model, const State& s,
                            std::vector<ContactMotion>& out) const {
  PairPositions q0, q1;
  const std::vector<int>& visit = touching(model, s);
  const std::vector<ContactPair>& pairs = candidates_;  // as touching() found them
  for (int i : visit) {
    const ContactPair& pair = pairs[i];
    if (!positions(pair, model, s, q0, q1, slack_)) continue;
    PairStart& start = startOf(i, model, s);
    const int sd = start.side;
    const double h = start.reach, f = start.face;
    const double p0 = start.p0, p1 = pairPenetration(q1, sd, h, f);
    if (p0 <= 0 && p1 <= 0) continue;
    formLaw(start, pair, s);
    const PairLaw& l = start.law;
    out.push_back({p0, p1, pairPenetrationRate(q0, pairValues(s.vn, pair), sd, h, f),
                   pairPenetrationRate(q1, pairValues(s.v, pair), sd, h, f), l.k, l.restitution,
                   l.q, l.c, start.mass});
  }
}

PairLaw MemberContact::law(const ContactPair& pair, const State& s, const PairPositions& q0,
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

double MemberContact::commit(const Model& model, State& s, int& pushed,
                             double& pushedEnergy) const {
  const std::vector<StepOutcome>& found = outcomes(model, s, lastRule_);
  const std::vector<ContactPair>& pairs = candidates_;  // as outcomes() found them
  nextMemory_.clear();
  if (nextMemory_.capacity() < pairs.size()) nextMemory_.reserve(2 * pairs.size());
  double released = 0, letGo = 0, crushed = 0;
  committedEnergy_ = 0;
  PairPositions q0, q1;
  for (const StepOutcome& f : found) {
    const ContactPair& pair = pairs[f.index];
    const PairMemory* m = memory(s, pair.key());
    const double full = f.full;
    const PairOutcome& o = f.outcome;
    const bool near = positions(pair, model, s, q0, q1, slack_);
    PairMemory next{pair.key(), 0.0, 0.0, o.stretch, distance(pair, m), m ? m->side : 0};
    bool flipped = false;
    // The offset shrinks with the penetration at the full distance (never
    // while the pair presses on: its force and energy are unchanged).
    if (m) next.offset = std::min(m->offset, std::max(full, 0.0));
    if (o.p1 > 0) {
      const double plain = std::max(m ? m->q : 0.0, o.p1);
      // A turn inside the step: the peak the pair's mass came back from.
      next.q = near ? pairLoadingPoint(data_, masses_, pair, s, q0, q1, side(m, q0), reach(pair, m),
                                       face(m), plain, o.p1)
                    : plain;
      crushed += crushingEnergy(data_.k, data_.restitution, plain, o.p1) -
                 crushingEnergy(data_.k, data_.restitution, next.q, o.p1);
      const int was = near ? side(m, q0) : 0;
      // A held side changes only past the centre line by the full distance.
      if (near && pairSide(q1) != was && (!next.side || o.p1 > reach(pair, m) + next.h)) {
        if (next.side) next.side = -next.side;
        // Seen from the new side the penetration is smaller (the loading point
        // kept, so that the energy only drops).
        const double seen = pairPenetration(q1, -was, reach(pair, m), face(&next));
        released += crushingEnergy(data_.k, data_.restitution, next.q, o.p1) -
                    crushingEnergy(data_.k, data_.restitution, next.q, seen);
        if (seen <= 0) next.q = 0;
        ++pushed;
        flipped = true;
      }
    }
    // A held side is let go once the node has cleared the centre line on it
    // by kLetGo of the contact distance, or gone as far around the end (from
    // then on the side at t_n is that side, and the contact distance it has
    // gained keeps it there), and when the offset is gone.
    const bool wasHeld = next.side != 0;
    if (next.side && (!near || next.offset <= 0 ||
                      pairPenetration(q1, next.side, 0.0, next.h) < -kLetGo * next.h))
      next.side = 0;
    // A held node can press on beyond the reach of the pair's boxes at the
    // committed positions alone (far on the wrong side beyond an end), where
    // energy() does not see it.
    const bool nearAfter = near && reachesAt(pair, q1);
    const bool kept = next.q > 0 || next.offset > 0 || next.stretch != 0;
    // Its energy at the committed state (as energy() finds it there).
    const double after =
        kept && nearAfter
            ? crushingEnergy(data_.k, data_.restitution, next.q,
                             pairPenetration(q1, side(&next, q1), reach(pair, &next), face(&next))) +
                  springFrictionEnergy(data_.k, next.stretch)
            : 0.0;
    committedEnergy_ += after;
    // What a held pair stored at the end of the step and does not store so
    // seen from its new side, or apart, is released (the trial energy counted
    // it; a pushed pair booked its own above). From the loading point it gets
    // now: what the new loading point took is in `crushed` already (taken
    // from the memory's, it was booked twice: the account's balance at such a
    // commit stood off by that much until the next step).
    if (wasHeld && !flipped)
      letGo += crushingEnergy(data_.k, data_.restitution, next.q, o.p1) +
               springFrictionEnergy(data_.k, o.stretch) - after;
    if (kept) nextMemory_.push_back(next);
  }
  // Candidates are sorted by key, so is the memory. Copied, with room to
  // double, so that steps allocate nothing while the contacts change little.
  if (s.pairs.capacity() < nextMemory_.size()) s.pairs.reserve(2 * nextMemory_.size());
  s.pairs.assign(nextMemory_.begin(), nextMemory_.end());
  committed_ = true;
  pushedEnergy += released;
  return released + letGo + crushed;
}

int MemberContact::membersSide(const ContactPair& pair, const Model& model, const State& s,
                               const PairPositions& q) const {
  // The far ends of the node's members (the elements at its joint group) seen
  // from the segment's line; members along the line tell nothing.
  const Vec2 t = q.b - q.a;
  const double l = t.norm();
  if (l == 0) return 0;
  int found = 0;
  for (int e : live_) {
    const auto nodes = model.element(e).nodes();
    for (int end = 0; end < 2; ++end) {
      if (group_[nodes[end]] != group_[pair.node]) continue;
      const int far = nodes[1 - end];
      const Vec2 x = model.coord(far) + Vec2(s.u[3 * far], s.u[3 * far + 1]);
      const double d = (t.x() * (x - q.a).y() - t.y() * (x - q.a).x()) / l;
      if (std::abs(d) <= kAlongLine * pair.h) continue;
      const int sd = d > 0 ? 1 : -1;
      if (found && sd != found) return 0;  // members on both sides
      found = sd;
    }
  }
  return found;
}

void MemberContact::openPairs(const Model& model, State& s) const {
  // Pairs in memory keep the contact distance they met at: the candidates'
  // boxes reach as far as the largest excess over the present distances.
  slack_ = 0;
  for (const PairMemory& m : s.pairs) {
    const int node = static_cast<int>(m.key >> 32), element = static_cast<int>(m.key & 0xffffffffu);
    if (node < static_cast<int>(nodeRadius_.size()) && element < model.numElements() &&
        model.hasElement(element))
      slack_ = std::max(slack_, m.h - nodeRadius_[node] - elementRadius_[element]);
  }
  // Room for four pairs in contact per node before a commit must allocate.
  const std::size_t room = 4 * contactNodes_.size();
  if (s.pairs.capacity() < room) s.pairs.reserve(room);
  if (nextMemory_.capacity() < room) nextMemory_.reserve(room);
  PairPositions q0, q1;
  // The new pairs gathered apart: appended to the memory they would unsort
  // it for the lookups of the pairs after them.
  nextMemory_.clear();
  for (const ContactPair& pair : candidates(model, s)) {
    if (memory(s, pair.key()) || !positions(pair, model, s, q0, q1)) continue;
    // A node on the segment itself (a ruptured joint's end node, on the
    // centre line of the member it was joined to) has no side of its own.
    const bool onSegment = pairPenetration(q1, pairSide(q1), pair.h) >= (1 - kOnSegment) * pair.h;
    const int sd = onSegment ? membersSide(pair, model, s, q1) : 0;
    const double p = pairPenetration(q1, sd ? sd : pairSide(q1), pair.h, sd ? pair.h : 0.0);
    if (p <= 0) continue;
    nextMemory_.push_back({pair.key(), 0.0, p, 0.0, pair.h, sd});
  }
  if (nextMemory_.empty()) return;
  s.pairs.insert(s.pairs.end(), nextMemory_.begin(), nextMemory_.end());
  std::sort(s.pairs.begin(), s.pairs.end(),
            [](const PairMemory& a, const PairMemory& b) { return a.key < b.key; });
}

}  // namespace c2d
