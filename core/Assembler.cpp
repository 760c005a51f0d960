#include "core/Assembler.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/contact/ContactDamper.h"
#include "core/FloorLoad.h"
#include "core/contact/GroundContact.h"
#include "core/contact/MemberContact.h"
#include "core/contact/SpringFriction.h"
#include "core/NodeMass.h"

namespace c2d {

Assembler::Assembler(Model& model) : model_(model) {}

bool Assembler::refresh() {
  if (patternVersion_ == model_.topologyVersion() && dofs_.numNodes() == model_.numNodes() &&
      (members_ != nullptr) == model_.memberContact().has_value())
    return false;
  dofs_ = DofMap(model_);
  stretch_.resize(0);  // until the next assembly: the committed stretches
  members_ = model_.memberContact() ? std::make_unique<MemberContact>(model_, dofs_) : nullptr;
  patternPairs_.clear();
  // With member contact the pattern waits for the first assembly, where the
  // pairs with a force are known: built here without them, it was built again
  // at once whenever a pair touched (after every joint formed in a fall).
  patternPending_ = members_ != nullptr;
  if (!patternPending_) buildPattern();
  const Eigen::Index nd = static_cast<Eigen::Index>(model_.numNodes()) * kNodeDofs;
  r_.setZero(nd);
  fRel_.setZero(nd);
  elemForce_.assign(model_.numElements(), ElemVec::Zero());
  fContact_.setZero(nd);
  fRef_.setZero(nd);
  fGrav_.setZero(nd);
  for (int n = 0; n < model_.numNodes(); ++n)
    for (int d = 0; d < kNodeDofs; ++d)
      if (!dofs_.restrained(n, d)) fRef_[n * kNodeDofs + d] = model_.force(n)[d];
  if (model_.gravity().squaredNorm() > 0) {
    for (int e = 0; e < model_.numElements(); ++e) {
      if (!model_.hasElement(e)) continue;
      const Element& el = model_.element(e);
      const ElemVec fe = el.bodyLoad(model_.gravity());
      const auto nodes = el.nodes();
      for (int a = 0; a < 2; ++a)
        for (int d = 0; d < kNodeDofs; ++d) fGrav_[nodes[a] * kNodeDofs + d] += fe[a * kNodeDofs + d];
    }
  }
  // Floor loads (QLOAd) and the weight of nodal masses: constant, like self-weight.
  fGrav_ += floorLoadVector(model_);
  mNodal_ = lumpedNodalMass(model_);
  masses_ = translationalMasses(model_);
  groundDamping_.assign(model_.numNodes(), 0.0);
  groundStick_.assign(model_.numNodes(), 0.0);
  if (const auto& ground = model_.ground())
    for (int n = 0; n < model_.numNodes(); ++n) {
      groundDamping_[n] = damperCoefficient(ground->zeta, ground->k, masses_[n]);
      groundStick_[n] = frictionStickDamping(ground->k, masses_[n]);
    }
  patternVersion_ = model_.topologyVersion();
  return true;
}

void Assembler::buildPattern() {
  const int neq = dofs_.numEquations();
  std::vector<Eigen::Triplet<double, int>> trip;
  trip.reserve(static_cast<size_t>(model_.numElements()) * kElemDofs * kElemDofs + neq);
  for (int i = 0; i < neq; ++i) trip.emplace_back(i, i, 0.0);
  for (int e = 0; e < model_.numElements(); ++e) {
    if (!model_.hasElement(e)) continue;
    const auto eq = dofs_.elementEqs(model_.element(e));
    for (int i : eq)
      if (i >= 0)
        for (int j : eq)
          if (j >= 0) trip.emplace_back(i, j, 0.0);
  }
  // Member contact pairs: the translations of the node and of the segment's ends.
  auto pairEqs = [&](std::uint64_t key) {
    const int node = static_cast<int>(key >> 32), element = static_cast<int>(key & 0xffffffffu);
    const auto ends = model_.element(element).nodes();
    const int nodes[3] = {node, ends[0], ends[1]};
    std::array<int, 6> eq;
    for (int a = 0; a < 3; ++a)
      for (int d = 0; d < 2; ++d) eq[2 * a + d] = dofs_.eq(nodes[a], d);
    return eq;
  };
  for (std::uint64_t key : patternPairs_) {
    const auto eq = pairEqs(key);
    for (int i : eq)
      if (i >= 0)
        for (int j : eq)
          if (j >= 0) trip.emplace_back(i, j, 0.0);
  }
  K_.resize(neq, neq);
  K_.setFromTriplets(trip.begin(), trip.end());
  K_.makeCompressed();

  auto position = [&](int i, int j) {
    const int* begin = K_.innerIndexPtr() + K_.outerIndexPtr()[j];
    const int* end = K_.innerIndexPtr() + K_.outerIndexPtr()[j + 1];
    const int* it = std::lower_bound(begin, end, i);
    return static_cast<int>(it - K_.innerIndexPtr());
  };
  elemPos_.assign(model_.numElements(), {});
  for (int e = 0; e < model_.numElements(); ++e) {
    if (!model_.hasElement(e)) continue;
    const auto eq = dofs_.elementEqs(model_.element(e));
    auto& pos = elemPos_[e];
    for (int a = 0; a < kElemDofs; ++a)
      for (int b = 0; b < kElemDofs; ++b)
        pos[a * kElemDofs + b] = (eq[a] >= 0 && eq[b] >= 0) ? position(eq[a], eq[b]) : -1;
  }
  diagPos_.resize(neq);
  for (int i = 0; i < neq; ++i) diagPos_[i] = position(i, i);
  uvPos_.assign(model_.numNodes(), -1);
  for (int n = 0; n < model_.numNodes(); ++n) {
    const int eu = dofs_.eq(n, 0), ev = dofs_.eq(n, 1);
    if (dofs_.used(n) && eu >= 0 && ev >= 0) uvPos_[n] = position(eu, ev);
  }
  pairPos_.resize(patternPairs_.size());
  for (std::size_t p = 0; p < patternPairs_.size(); ++p) {
    const auto eq = pairEqs(patternPairs_[p]);
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b)
        pairPos_[p][a * 6 + b] = (eq[a] >= 0 && eq[b] >= 0) ? position(eq[a], eq[b]) : -1;
  }
  ++structureVersion_;
  patternPending_ = false;
}

void Assembler::evaluateMemberContact(const State& s, const StepRule& rule, bool wantTangent) {
  contactForces_.clear();
  if (!members_) return;
  auto slotOf = [&](const ContactPair& p) {
    const auto it = std::lower_bound(patternPairs_.begin(), patternPairs_.end(), p.key());
    return it != patternPairs_.end() && *it == p.key()
               ? static_cast<int>(it - patternPairs_.begin())
               : -1;
  };
  bool missing = false;
  PairVec f;
  PairMat k;
  const double extra = members_->slack();
  const MemberContact::Nearby nearby = members_->nearby(model_, s, extra);
  members_->assembling(rule, !nearby.reach.empty());
  const std::vector<ContactPair>& candidates = nearby.candidates;
  for (int i : nearby.near) {
    if (!members_->evaluate(i, model_, s, rule, wantTangent, f, k)) continue;
    const ContactPair& p = candidates[i];
    const int slot = slotOf(p);
    missing = missing || slot < 0;
    contactForces_.push_back({p, slot, f, k});
  }
  if (patternPending_ && !(missing && wantTangent)) {
    buildPattern();  // no pairs (they get places when a tangent needs them)
    return;
  }
  if (!missing || !wantTangent) return;
  // The pattern gets the candidates within a quarter of the search margin of
  // touching: the pairs about to touch, not every pair of the search (whose
  // couplings would only add fill to the factors). Within by their
  // penetration, not only by their boxes: the boxes of members lying along
  // each other overlap far beyond it (docs/design/member-contact.md).
  patternPairs_.clear();
  const double reserve = 0.25 * members_->margin();
  // (The pairs with a force always: they are candidates, in the same order.)
  std::size_t next = 0;
  for (const ContactPair& p : candidates) {
    const bool force = next < contactForces_.size() && contactForces_[next].pair.key() == p.key();
    if (force) ++next;
    if (force || (members_->sweptReach(p, reserve) && members_->within(p, model_, s, reserve)))
      patternPairs_.push_back(p.key());
  }
  buildPattern();
  for (PairForce& pf : contactForces_) pf.slot = slotOf(pf.pair);
}

void Assembler::restartContactSearch() {
  if (!members_) return;
  members_ = std::make_unique<MemberContact>(model_, dofs_);
  patternPairs_.clear();
  buildPattern();
}

Status Assembler::assemble(const State& s, const StepRule& rule,
                           const Eigen::VectorXd& loadFactors, bool wantTangent) {
  refresh();
  evaluateMemberContact(s, rule, wantTangent);
  r_ = -loadFactors.cwiseProduct(fRef_) - fGrav_;
  releasedLoadAt(s, rule);
  r_ -= fRel_;
  forceScale_ = r_.size() ? r_.cwiseAbs().maxCoeff() : 0.0;
  if (wantTangent) std::fill(K_.valuePtr(), K_.valuePtr() + K_.nonZeros(), 0.0);

  if (Status st = assembleElements(s, rule, wantTangent); !st) return st;
  if (Status st = addNodalInertia(s, rule, wantTangent); !st) return st;
  addGroundContact(s, rule, wantTangent);
  addPairContact(wantTangent);
  return Status::success();
}

Status Assembler::assembleElements(const State& s, const StepRule& rule, bool wantTangent) {
  ElementKinematics kin;
  ElemVec re;
  ElemMat ke;
  for (int e = 0; e < model_.numElements(); ++e) {
    if (!model_.hasElement(e)) continue;
    Element& el = model_.element(e);
    kin = s.kinematics(el.nodes());
    const Status st = el.evaluate(kin, rule, wantTangent, re, ke);
    if (!st) return Status::failure("element " + std::to_string(e + 1) + ": " + st.why);
    if (!re.allFinite() || (wantTangent && !ke.allFinite()))
      return Status::failure("element " + std::to_string(e + 1) + ": non-finite residual or tangent");
    elemForce_[e] = re;
    forceScale_ = std::max(forceScale_, re.cwiseAbs().maxCoeff());
    const auto nodes = el.nodes();
    for (int a = 0; a < 2; ++a)
      r_.segment<kNodeDofs>(static_cast<Eigen::Index>(nodes[a]) * kNodeDofs) +=
          re.segment<kNodeDofs>(a * kNodeDofs);
    if (wantTangent) {
      const auto& pos = elemPos_[e];
      double* values = K_.valuePtr();
      for (int a = 0; a < kElemDofs; ++a)
        for (int b = 0; b < kElemDofs; ++b)
          if (pos[a * kElemDofs + b] >= 0) values[pos[a * kElemDofs + b]] += ke(a, b);
    }
  }
  return Status::success();
}

Status Assembler::addNodalInertia(const State& s, const StepRule& rule, bool wantTangent) {
  // Lumped nodal masses (MASS, QLOAd carried as mass): inertia m a_eff per dof.
  if (rule.dynamic()) {
    for (Eigen::Index i = 0; i < mNodal_.size(); ++i) {
      if (mNodal_[i] == 0 || !dofs_.used(static_cast<int>(i / kNodeDofs))) continue;
      const double du = s.u[i] - s.un[i];
      if (i % kNodeDofs == 2 && !rule.rotationInRange(du))
        return Status::failure("node " + std::to_string(i / kNodeDofs + 1) + ": " +
                               StepRule::kRotationRangeMessage);
      r_[i] += mNodal_[i] * rule.acceleration(rule.rate(i, du), s.vn[i], s.an[i]);
      const int eq = dofs_.eq(static_cast<int>(i));
      if (wantTangent && eq >= 0)
        K_.valuePtr()[diagPos_[eq]] += mNodal_[i] * rule.ca * rule.rateSlope(i, du);
    }
  }
  return Status::success();
}

void Assembler::addGroundContact(const State& s, const StepRule& rule, bool wantTangent) {
  if (const auto& ground = model_.ground()) {
    fContact_.setZero();
    // The friction springs' stretches at the end of the step: none off the
    // ground (or on a node moving with a joint's master).
    if (ground->mu > 0) {
      stretch_.setZero(model_.numNodes());
      stretchU_ = s.u;
      stretchUn_ = s.un;
    }
    for (int n = 0; n < model_.numNodes(); ++n) {
      // A shared joint's slave moves with its master: its contact is the master's.
      if (!dofs_.used(n) || dofs_.aliased(n)) continue;
      const Eigen::Index iv = static_cast<Eigen::Index>(n) * kNodeDofs + 1;
      const double y0 = model_.coord(n).y();
      const ContactForce c = groundContact(*ground, s.crush[n], y0 + s.un[iv], y0 + s.u[iv], rule,
                                           {groundDamping_[n], s.vn[iv], s.an[iv]});
      if (c.force == 0 && c.tangent == 0) continue;
      r_[iv] -= c.force;
      fContact_[iv] = c.force;
      const int eq = dofs_.eq(n, 1);
      if (wantTangent && eq >= 0) K_.valuePtr()[diagPos_[eq]] += c.tangent;
      if (ground->mu <= 0) continue;
      const Eigen::Index iu = iv - 1;
      const FrictionForce fr =
          groundFriction(*ground, c, s.un[iu] - s.stretch[n], s.un[iu], s.u[iu], rule, groundStick_[n]);
      stretch_[n] = s.u[iu] - fr.anchor;
      r_[iu] -= fr.force;
      fContact_[iu] = fr.force;
      const int equ = dofs_.eq(n, 0);
      if (wantTangent && equ >= 0) {
        K_.valuePtr()[diagPos_[equ]] -= fr.dx;
        if (uvPos_[n] >= 0) K_.valuePtr()[uvPos_[n]] -= fr.dy;
      }
    }
  }
}

void Assembler::addPairContact(bool wantTangent) {
  for (const PairForce& pf : contactForces_) {
    const int nodes[3] = {pf.pair.node, pf.pair.a, pf.pair.b};
    for (int a = 0; a < 3; ++a)
      r_.segment<2>(static_cast<Eigen::Index>(nodes[a]) * kNodeDofs) += pf.force.segment<2>(2 * a);
    forceScale_ = std::max(forceScale_, pf.force.cwiseAbs().maxCoeff());
    if (!wantTangent || pf.slot < 0) continue;
    const auto& pos = pairPos_[pf.slot];
    double* values = K_.valuePtr();
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b)
        if (pos[a * 6 + b] >= 0) values[pos[a * 6 + b]] += pf.tangent(a, b);
  }
}

void Assembler::releasedLoadAt(const State& s, const StepRule& rule) {
  fRel_.setZero();
  const bool midPoint = rule.scheme == Scheme::MidPoint;
  for (const ReleasedForce& f : model_.releasedForces()) {
    const double w = midPoint ? 0.5 * (f.factor(s.tn) + f.factor(s.t)) : f.factor(s.t);
    if (w == 0) continue;
    for (int a = 0; a < 2; ++a)
      if (f.nodes[a] >= 0)
        fRel_.segment<kNodeDofs>(static_cast<Eigen::Index>(f.nodes[a]) * kNodeDofs) +=
            w * f.force.segment<kNodeDofs>(a * kNodeDofs);
  }
}

void Assembler::toEquations(const Eigen::VectorXd& nodal, Eigen::VectorXd& eqs) const {
  eqs.setZero(dofs_.numEquations());
  for (Eigen::Index i = 0; i < nodal.size(); ++i) {
    const int eq = dofs_.eq(static_cast<int>(i));
    if (eq >= 0) eqs[eq] += nodal[i];
  }
}

double Assembler::strainEnergy() const {
  double w = 0;
  for (int e = 0; e < model_.numElements(); ++e)
    if (model_.hasElement(e)) w += model_.element(e).strainEnergy();
  return w;
}

double Assembler::contactEnergy(const State& s) {
  double w = 0;
  if (members_) {
    // At the committed positions the member contact's last commit found the
    // energy (the same sum), without another pass over the pairs.
    const bool committed = s.u.size() == s.un.size() && s.u == s.un;
    w = committed ? members_->committedEnergy(model_, s) : members_->energy(model_, s);
  }
  const auto& ground = model_.ground();
  if (!ground) return w;
  const Eigen::VectorXd& stretches = stretchesOf(s);
  for (int n = 0; n < model_.numNodes(); ++n)
    if (dofs_.used(n) && !dofs_.aliased(n)) {
      const Eigen::Index i = static_cast<Eigen::Index>(n) * kNodeDofs;
      w += c2d::contactEnergy(*ground, s.crush[n], model_.coord(n).y() + s.u[i + 1]);
      if (ground->mu > 0) w += frictionEnergy(*ground, stretches[n]);
    }
  return w;
}

double Assembler::commitContact(State& s, const StepRule& rule, double* given) {
  const double released =
      members_ ? members_->commit(model_, s, pushedThrough_, pushedThroughEnergy_) : 0.0;
  const auto& ground = model_.ground();
  if (!ground) return released;
  // A node whose turn fell inside the step gets the peak it came back from
  // (core/contact/CrushingLaw.h): the energy that takes from its contact is
  // dissipated. What the scheme's decay took from an impact is given back
  // (groundImpactOwed), apart.
  double crushed = 0, back = 0;
  const bool rates = s.v.size() == s.u.size() && s.vn.size() == s.u.size();
  for (int n = 0; n < model_.numNodes(); ++n) {
    const Eigen::Index i = static_cast<Eigen::Index>(n) * kNodeDofs;
    const double y = model_.coord(n).y() + s.u[i + 1];
    const bool moves = rates && dofs_.used(n) && !dofs_.aliased(n);
    double q = moves ? loadingPoint(*ground, s.crush[n], masses_[n], y, s.vn[i + 1], s.v[i + 1])
                     : loadingPoint(*ground, s.crush[n], 0.0, y, 0.0, 0.0);
    if (q > s.crush[n] && penetration(*ground, y) < q)
      crushed += c2d::contactEnergy(*ground, s.crush[n], y) - c2d::contactEnergy(*ground, q, y);
    if (moves) {
      const double p0 = penetration(*ground, model_.coord(n).y() + s.un[i + 1]);
      const ImpactOwed o = groundImpactOwed(*ground, s.crush[n], q, s.owed[n], p0,
                                            penetration(*ground, y), masses_[n], s.vn[i + 1],
                                            s.v[i + 1], rule);
      q = o.q;
      s.owed[n] = o.owed;
      back += o.given;
    } else {
      s.owed[n] = 0;
    }
    s.crush[n] = q;
  }
  const Eigen::VectorXd& stretches = stretchesOf(s);
  if (&stretches != &s.stretch) s.stretch = stretches;
  if (given) *given = back;
  return released + crushed;
}

const Eigen::VectorXd& Assembler::stretchesOf(const State& s) const {
  const bool evaluated = stretch_.size() == model_.numNodes() && stretchU_.size() == s.u.size() &&
                         stretchUn_.size() == s.un.size() && stretchU_ == s.u &&
                         stretchUn_ == s.un;
  return evaluated ? stretch_ : s.stretch;
}

double Assembler::contactDissipation(const State& s, const StepRule& rule) {
  double d = members_ ? members_->dissipation(model_, s, rule) : 0.0;
  const auto& ground = model_.ground();
  if (!ground) return d;
  for (int n = 0; n < model_.numNodes(); ++n) {
    if (!dofs_.used(n) || dofs_.aliased(n)) continue;
    const Eigen::Index i = static_cast<Eigen::Index>(n) * kNodeDofs;
    const Vec2& X = model_.coord(n);
    d += groundDissipation(*ground, s.crush[n], X.x() + s.un[i] - s.stretch[n], X.x() + s.un[i],
                           X.y() + s.un[i + 1], X.x() + s.u[i], X.y() + s.u[i + 1], rule,
                           {groundDamping_[n], s.vn[i + 1], s.an[i + 1]}, groundStick_[n]);
  }
  return d;
}

void Assembler::contactMotions(const State& s, std::vector<ContactMotion>& out) {
  out.clear();
  if (const auto& ground = model_.ground())
    for (int n = 0; n < model_.numNodes(); ++n) {
      if (!dofs_.used(n) || dofs_.aliased(n)) continue;
      const Eigen::Index i = static_cast<Eigen::Index>(n) * kNodeDofs + 1;
      const double y = model_.coord(n).y();
      const double p0 = penetration(*ground, y + s.un[i]), p1 = penetration(*ground, y + s.u[i]);
      if (p0 > 0 || p1 > 0)
        out.push_back({p0, p1, -s.vn[i], -s.v[i], ground->k, ground->restitution, s.crush[n],
                       groundDamping_[n], masses_[n]});
    }
  if (members_) members_->motions(model_, s, out);
  const double g = model_.gravity().norm();
  for (ContactMotion& c : out)
    if (c.m > 0 && std::isfinite(c.m) && c.k > 0) c.rest = 0.5 * (c.m * g) * (c.m * g) / c.k;
}

Assembler::Momentum Assembler::momentum(const State& s) const {
  Momentum out;
  auto add = [&](int node, const Vec3& p) {
    const Vec2 x = model_.coord(node) + s.u.segment<2>(static_cast<Eigen::Index>(node) * kNodeDofs);
    out.linear += p.head<2>();
    out.angular += x.x() * p.y() - x.y() * p.x() + p.z();
  };
  for (int e = 0; e < model_.numElements(); ++e) {
    if (!model_.hasElement(e)) continue;
    const Element& el = model_.element(e);
    const auto nodes = el.nodes();
    const ElemVec p = el.momentum(s.velocities(nodes));
    for (int a = 0; a < 2; ++a) add(nodes[a], p.segment<kNodeDofs>(a * kNodeDofs));
  }
  for (int n = 0; n < model_.numNodes(); ++n) {
    const Eigen::Index i = static_cast<Eigen::Index>(n) * kNodeDofs;
    if (i + 2 >= mNodal_.size() || !dofs_.used(n)) continue;
    const Vec3 m = mNodal_.segment<kNodeDofs>(i);
    if (!m.isZero(0)) add(n, m.cwiseProduct(Vec3(s.v.segment<kNodeDofs>(i))));
  }
  return out;
}

double Assembler::kineticEnergy(const State& s) const {
  double w = 0;
  for (int e = 0; e < model_.numElements(); ++e)
    if (model_.hasElement(e)) {
      const Element& el = model_.element(e);
      w += el.kineticEnergy(s.velocities(el.nodes()));
    }
  for (Eigen::Index i = 0; i < mNodal_.size(); ++i)
    if (mNodal_[i] != 0 && dofs_.used(static_cast<int>(i / kNodeDofs)))
      w += 0.5 * mNodal_[i] * s.v[i] * s.v[i];
  return w;
}

}  // namespace c2d
