#include "elements/InfillStrut.h"

#include <cmath>

namespace c2d {

namespace {

using namespace checkpoint;

constexpr std::array<int, 4> kTranslations{0, 1, kNodeDofs, kNodeDofs + 1};

}  // namespace

InfillStrut::InfillStrut(const InfillStrutData& data) : d_(data) {
  const Vec2 chord = d_.x2 - d_.x1;
  length_ = chord.norm();
  if (!(length_ > 0)) throw std::invalid_argument("infill strut of zero length");
  e0_ = chord / length_;
}

double InfillStrut::strain(const ElemVec& d, Eigen::Vector4d* b) const {
  const Vec2 du(d(3) - d(0), d(4) - d(1));
  if (!d_.finite) {
    if (b) *b << -e0_, e0_;
    if (b) *b /= length_;
    return e0_.dot(du) / length_;
  }
  const Vec2 dx = d_.x2 - d_.x1 + du;
  const double l2 = length_ * length_;
  if (b) *b << -dx / l2, dx / l2;
  return (dx.squaredNorm() - l2) / (2 * l2);
}

Status InfillStrut::evaluate(const ElementKinematics& kin, const StepRule& rule, bool wantTangent,
                             ElemVec& residual, ElemMat& tangent) {
  const bool mid = rule.scheme == Scheme::MidPoint;
  const double w = mid ? 0.5 + rule.alpha : 1.0;  // weight of eps_n+1 in the law's strain
  const double c = mid ? 0.5 : 1.0;               // weight of x_n+1 in the configuration of B
  Eigen::Vector4d b1, b0;
  const double eps1 = strain(kin.d, &b1);
  const double eps0 = mid ? strain(kin.dn, &b0) : eps1;
  if (!mid) b0 = b1;
  if (!std::isfinite(eps1) || !std::isfinite(eps0))
    return Status::failure("infill strut: non-finite strain");
  const Eigen::Vector4d bc = c * b1 + (1 - c) * b0;
  const StrutResponse r = d_.law.evaluate(w * eps1 + (1 - w) * eps0, committed_);
  trial_ = r.state;
  force_ = r.N;
  energy_ = length_ * (mid ? d_.law.evaluate(eps1, committed_).energy : r.energy);

  residual.setZero();
  const Eigen::Vector4d f = length_ * r.N * bc;
  for (int i = 0; i < 4; ++i) residual(kTranslations[i]) = f(i);
  if (wantTangent) {
    tangent.setZero();
    Eigen::Matrix4d k = length_ * r.dN * w * bc * b1.transpose();
    if (d_.finite && r.N != 0) {
      const double h = length_ * r.N * c / (length_ * length_);
      for (int i = 0; i < 2; ++i) {
        k(i, i) += h;
        k(i + 2, i + 2) += h;
        k(i, i + 2) -= h;
        k(i + 2, i) -= h;
      }
    }
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) tangent(kTranslations[i], kTranslations[j]) = k(i, j);
  }
  if (rule.dynamic())
    rule.addInertia(mass(), kin.d - kin.dn, kin.vn, kin.an, residual,
                    wantTangent ? &tangent : nullptr);
  return Status::success();
}

ElemMat InfillStrut::mass() const {
  ElemMat m = ElemMat::Zero();
  for (int i : kTranslations) m(i, i) = d_.nodeMass;
  return m;
}

ElemVec InfillStrut::bodyLoad(const Vec2& g) const {
  ElemVec f = ElemVec::Zero();
  for (int a = 0; a < 2; ++a) f.segment<2>(a * kNodeDofs) = d_.nodeMass * g;
  return f;
}

void InfillStrut::writeState(std::ostream& out) const {
  for (int n : d_.nodes) put(out, n);
  putFixed(out, d_.x1);
  putFixed(out, d_.x2);
  put(out, d_.law.stiffness());
  put(out, d_.law.strength());
  put(out, d_.nodeMass);
  putBool(out, d_.finite);
  put(out, d_.panel);
  put(out, d_.partner);
  for (const StrutLawState* s : {&committed_, &trial_}) {
    put(out, s->kappa);
    putBool(out, s->gone);
    putBool(out, s->doomed);
  }
  put(out, force_);
  put(out, energy_);
}

void InfillStrut::readState(std::istream& in) {
  InfillStrutData d;
  for (int& n : d.nodes) n = get<int>(in);
  getFixed(in, d.x1);
  getFixed(in, d.x2);
  const double K = get<double>(in), Pu = get<double>(in);
  try {
    d.law = StrutLaw(K, Pu);
    d.nodeMass = get<double>(in);
    d.finite = getBool(in);
    d.panel = get<int>(in);
    d.partner = get<int>(in);
    *this = InfillStrut(d);
  } catch (const std::invalid_argument& e) {
    throw CheckpointError(std::string("infill strut: ") + e.what());
  }
  for (StrutLawState* s : {&committed_, &trial_}) {
    s->kappa = get<double>(in);
    s->gone = getBool(in);
    s->doomed = getBool(in);
  }
  force_ = get<double>(in);
  energy_ = get<double>(in);
}

}  // namespace c2d
