#include "core/Assembler.h"

#include <algorithm>
#include <string>

#include "core/FloorLoad.h"
#include "core/GroundContact.h"

namespace c2d {

Assembler::Assembler(Model& model) : model_(model) {}

bool Assembler::refresh() {
  if (patternVersion_ == model_.topologyVersion() && dofs_.numNodes() == model_.numNodes())
    return false;
  dofs_ = DofMap(model_);
  buildPattern();
  const Eigen::Index nd = static_cast<Eigen::Index>(model_.numNodes()) * kNodeDofs;
  r_.setZero(nd);
  fContact_.setZero(nd);
  fRef_.setZero(nd);
  fGrav_.setZero(nd);
  for (int n = 0; n < model_.numNodes(); ++n)
    for (int d = 0; d < kNodeDofs; ++d)
      if (!dofs_.restrained(n, d)) fRef_[n * kNodeDofs + d] = model_.force(n)[d];
  if (model_.gravity().squaredNorm() > 0) {
    for (int e = 0; e < model_.numElements(); ++e) {
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
  patternVersion_ = model_.topologyVersion();
  return true;
}

void Assembler::buildPattern() {
  const int neq = dofs_.numEquations();
  std::vector<Eigen::Triplet<double, int>> trip;
  trip.reserve(static_cast<size_t>(model_.numElements()) * kElemDofs * kElemDofs + neq);
  for (int i = 0; i < neq; ++i) trip.emplace_back(i, i, 0.0);
  for (int e = 0; e < model_.numElements(); ++e) {
    const auto eq = dofs_.elementEqs(model_.element(e));
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
    const auto eq = dofs_.elementEqs(model_.element(e));
    auto& pos = elemPos_[e];
    for (int a = 0; a < kElemDofs; ++a)
      for (int b = 0; b < kElemDofs; ++b)
        pos[a * kElemDofs + b] = (eq[a] >= 0 && eq[b] >= 0) ? position(eq[a], eq[b]) : -1;
  }
  diagPos_.resize(neq);
  for (int i = 0; i < neq; ++i) diagPos_[i] = position(i, i);
}

void Assembler::gather(const Element& e, const State& s, ElementKinematics& kin) const {
  const auto nodes = e.nodes();
  for (int a = 0; a < 2; ++a) {
    const Eigen::Index base = static_cast<Eigen::Index>(nodes[a]) * kNodeDofs;
    kin.d.segment<kNodeDofs>(a * kNodeDofs) = s.u.segment<kNodeDofs>(base);
    kin.dn.segment<kNodeDofs>(a * kNodeDofs) = s.un.segment<kNodeDofs>(base);
    kin.vn.segment<kNodeDofs>(a * kNodeDofs) = s.vn.segment<kNodeDofs>(base);
    kin.an.segment<kNodeDofs>(a * kNodeDofs) = s.an.segment<kNodeDofs>(base);
  }
}

Status Assembler::assemble(const State& s, const StepRule& rule,
                           const Eigen::VectorXd& loadFactors, bool wantTangent) {
  refresh();
  r_ = -loadFactors.cwiseProduct(fRef_) - fGrav_;
  forceScale_ = r_.size() ? r_.cwiseAbs().maxCoeff() : 0.0;
  if (wantTangent) std::fill(K_.valuePtr(), K_.valuePtr() + K_.nonZeros(), 0.0);

  ElementKinematics kin;
  ElemVec re;
  ElemMat ke;
  for (int e = 0; e < model_.numElements(); ++e) {
    Element& el = model_.element(e);
    gather(el, s, kin);
    const Status st = el.evaluate(kin, rule, wantTangent, re, ke);
    if (!st) return Status::failure("element " + std::to_string(e + 1) + ": " + st.why);
    if (!re.allFinite() || (wantTangent && !ke.allFinite()))
      return Status::failure("element " + std::to_string(e + 1) + ": non-finite residual or tangent");
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

  // Lumped nodal masses (MASS, QLOAd carried as mass): inertia m a_eff per dof.
  if (rule.dynamic()) {
    for (Eigen::Index i = 0; i < mNodal_.size(); ++i) {
      if (mNodal_[i] == 0 || !dofs_.used(static_cast<int>(i / kNodeDofs))) continue;
      r_[i] += mNodal_[i] * rule.acceleration(s.u[i] - s.un[i], s.vn[i], s.an[i]);
      const int eq = dofs_.eq(static_cast<int>(i));
      if (wantTangent && eq >= 0) K_.valuePtr()[diagPos_[eq]] += mNodal_[i] * rule.ca;
    }
  }

  if (const auto& ground = model_.ground()) {
    fContact_.setZero();
    for (int n = 0; n < model_.numNodes(); ++n) {
      // A shared joint's slave moves with its master: its contact is the master's.
      if (!dofs_.used(n) || dofs_.aliased(n)) continue;
      const Eigen::Index iv = static_cast<Eigen::Index>(n) * kNodeDofs + 1;
      const double y0 = model_.coord(n).y();
      const ContactForce c = groundContact(*ground, y0 + s.un[iv], y0 + s.u[iv], rule);
      if (c.force == 0 && c.tangent == 0) continue;
      r_[iv] -= c.force;
      fContact_[iv] = c.force;
      const int eq = dofs_.eq(n, 1);
      if (wantTangent && eq >= 0) K_.valuePtr()[diagPos_[eq]] += c.tangent;
    }
  }
  return Status::success();
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
  for (int e = 0; e < model_.numElements(); ++e) w += model_.element(e).strainEnergy();
  return w;
}

double Assembler::contactEnergy(const State& s) const {
  const auto& ground = model_.ground();
  if (!ground) return 0;
  double w = 0;
  for (int n = 0; n < model_.numNodes(); ++n)
    if (dofs_.used(n) && !dofs_.aliased(n))
      w += c2d::contactEnergy(*ground, model_.coord(n).y() + s.u[n * kNodeDofs + 1]);
  return w;
}

double Assembler::kineticEnergy(const State& s) const {
  double w = 0;
  ElemVec v;
  for (int e = 0; e < model_.numElements(); ++e) {
    const Element& el = model_.element(e);
    const auto nodes = el.nodes();
    for (int a = 0; a < 2; ++a)
      v.segment<kNodeDofs>(a * kNodeDofs) =
          s.v.segment<kNodeDofs>(static_cast<Eigen::Index>(nodes[a]) * kNodeDofs);
    w += el.kineticEnergy(v);
  }
  for (Eigen::Index i = 0; i < mNodal_.size(); ++i)
    if (mNodal_[i] != 0 && dofs_.used(static_cast<int>(i / kNodeDofs)))
      w += 0.5 * mNodal_[i] * s.v[i] * s.v[i];
  return w;
}

}  // namespace c2d
