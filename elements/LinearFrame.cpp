#include "elements/LinearFrame.h"

#include <Eigen/LU>
#include <cassert>
#include <cmath>

namespace c2d {

namespace {

// Global-to-element rotation of the six element dofs: d_local = T d_global.
ElemMat rotation(double c, double s) {
  ElemMat t = ElemMat::Zero();
  for (int a = 0; a < 2; ++a) {
    const int o = kNodeDofs * a;
    t(o, o) = c;
    t(o, o + 1) = s;
    t(o + 1, o) = -s;
    t(o + 1, o + 1) = c;
    t(o + 2, o + 2) = 1.0;
  }
  return t;
}

// Element-frame stiffness of the Timoshenko element: l B^T C B with B the
// strain operator (eps, gamma, kappa) at the midpoint.
ElemMat timoshenkoStiffness(double l, double ea, double ga, double ei) {
  Eigen::Matrix<double, 3, kElemDofs> b;
  b << -1 / l, 0, 0, 1 / l, 0, 0,        //
      0, -1 / l, -0.5, 0, 1 / l, -0.5,  //
      0, 0, -1 / l, 0, 0, 1 / l;
  const Vec3 c(ea, ga, ei);
  return l * b.transpose() * c.asDiagonal() * b;
}

ElemMat eulerBernoulliStiffness(double l, double ea, double ei) {
  ElemMat k = ElemMat::Zero();
  const double a = ea / l;
  k(0, 0) = k(3, 3) = a;
  k(0, 3) = k(3, 0) = -a;
  const int idx[4] = {1, 2, 4, 5};
  const double l2 = l * l;
  const double kb[4][4] = {{12, 6 * l, -12, 6 * l},
                           {6 * l, 4 * l2, -6 * l, 2 * l2},
                           {-12, -6 * l, 12, -6 * l},
                           {6 * l, 2 * l2, -6 * l, 4 * l2}};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) k(idx[i], idx[j]) = ei / (l2 * l) * kb[i][j];
  return k;
}

// Consistent mass with linear shape functions for every dof (translational
// part is isotropic, hence the same in any frame).
ElemMat linearConsistentMass(double l, double rhoA, double rhoI) {
  ElemMat m = ElemMat::Zero();
  for (int i = 0; i < kNodeDofs; ++i) {
    const double mu = (i < 2 ? rhoA : rhoI) * l / 6.0;
    m(i, i) = m(i + 3, i + 3) = 2 * mu;
    m(i, i + 3) = m(i + 3, i) = mu;
  }
  return m;
}

// Element-frame consistent mass of the Euler-Bernoulli element: linear axial,
// cubic Hermite transverse, rotary inertia rhoI with the rotation v' of the
// same cubic.
ElemMat hermiteConsistentMass(double l, double rhoA, double rhoI) {
  ElemMat m = ElemMat::Zero();
  m(0, 0) = m(3, 3) = rhoA * l / 3.0;
  m(0, 3) = m(3, 0) = rhoA * l / 6.0;
  const int idx[4] = {1, 2, 4, 5};
  const double l2 = l * l;
  const double mt[4][4] = {{156, 22 * l, 54, -13 * l},
                           {22 * l, 4 * l2, 13 * l, -3 * l2},
                           {54, 13 * l, 156, -22 * l},
                           {-13 * l, -3 * l2, -22 * l, 4 * l2}};
  const double mr[4][4] = {{36, 3 * l, -36, 3 * l},
                           {3 * l, 4 * l2, -3 * l, -l2},
                           {-36, -3 * l, 36, -3 * l},
                           {3 * l, -l2, -3 * l, 4 * l2}};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      m(idx[i], idx[j]) = rhoA * l / 420.0 * mt[i][j] + rhoI / (30.0 * l) * mr[i][j];
  return m;
}

ElemMat lumpedMass(double l, double rhoA, double rhoI) {
  ElemVec diag;
  diag << rhoA, rhoA, rhoI, rhoA, rhoA, rhoI;
  return (0.5 * l * diag).asDiagonal();
}

}  // namespace

LinearFrame::LinearFrame(const MaterialSet& mat, const std::array<int, 2>& nodes,
                         const Vec2& x1, const Vec2& x2, const std::array<double, 2>& offsets)
    : nodes_(nodes),
      materialNumber_(mat.number),
      shear_(mat.shear),
      rigid_(x1, x2, offsets[0], offsets[1]),
      ea_(mat.EA()),
      ga_(mat.GA()),
      ei_(mat.EI()),
      rhoA_(mat.rhoA()),
      damping_(mat.dampingA1) {
  const double full = (x2 - x1).norm();
  assert(full > 0 && "element of zero length");
  length_ = full - offsets[0] - offsets[1];
  cos_ = (x2.x() - x1.x()) / full;
  sin_ = (x2.y() - x1.y()) / full;
  const ElemMat t = rotation(cos_, sin_);
  const ElemMat kLocal = shear_ ? timoshenkoStiffness(length_, ea_, ga_, ei_)
                                : eulerBernoulliStiffness(length_, ea_, ei_);
  const ElemMat tg = t * rigid_.linearMap();
  stiffness_ = tg.transpose() * kLocal * tg;
  // The rigid zones' mass belongs to the joint region: the full length's.
  if (mat.mass == MassType::Lumped) {
    mass_ = lumpedMass(full, rhoA_, mat.rhoI());
  } else if (shear_) {
    mass_ = linearConsistentMass(full, rhoA_, mat.rhoI());
  } else {
    mass_ = t.transpose() * hermiteConsistentMass(full, rhoA_, mat.rhoI()) * t;
  }
}

std::string LinearFrame::typeName() const {
  return shear_ ? "frame-timoshenko" : "frame-euler-bernoulli";
}

SectionForces LinearFrame::forcesAt(const ElemVec& d) const {
  const ElemVec dl = rotation(cos_, sin_) * (rigid_.linearMap() * d);
  const double l = length_;
  SectionForces f;
  f.N = ea_ * (dl(3) - dl(0)) / l;
  // Both interpolations give kappa(l/2) = (theta2 - theta1)/l.
  f.M = ei_ * (dl(5) - dl(2)) / l;
  if (shear_) {
    f.V = ga_ * ((dl(4) - dl(1)) / l - 0.5 * (dl(2) + dl(5)));
  } else {
    // Moment equilibrium M' + V = 0 with M = EI v'' of the Hermite cubic.
    f.V = -ei_ * (12 * (dl(1) - dl(4)) / (l * l * l) + 6 * (dl(2) + dl(5)) / (l * l));
  }
  return f;
}

Status LinearFrame::evaluate(const ElementKinematics& kin, const StepRule& rule,
                             bool wantTangent, ElemVec& residual, ElemMat& tangent) {
  double wk = 1.0;  // weight of d_{n+1} in the stiffness term
  if (rule.scheme == Scheme::MidPoint) {
    wk = 0.5 + rule.alpha;
    const ElemVec dAlg = wk * kin.d + (0.5 - rule.alpha) * kin.dn;
    residual = stiffness_ * (dAlg - d0_);
  } else {
    residual = stiffness_ * (kin.d - d0_);
  }
  // The section's dashpot: a1 K (d - dn)/h.
  if (const double f = damping_.factor(rule); f > 0) {
    residual += f * (stiffness_ * (kin.d - kin.dn));
    wk += f;
  }
  if (wantTangent) tangent = wk * stiffness_;
  if (rule.dynamic()) {
    const ElemVec dd = kin.d - kin.dn;
    if (!rule.rotationsInRange(dd)) return Status::failure(StepRule::kRotationRangeMessage);
    rule.pairWithRate(dd, residual, wantTangent ? &tangent : nullptr);
    rule.addInertia(mass_, dd, kin.vn, kin.an, residual, wantTangent ? &tangent : nullptr);
  }
  if (!residual.allFinite()) return Status::failure("frame element: non-finite residual");

  const ElemVec dElastic = kin.d - d0_;
  trial_.energy = 0.5 * dElastic.dot(stiffness_ * dElastic);
  trial_.forces = forcesAt(dElastic);
  return Status::success();
}

ElemVec LinearFrame::bodyLoad(const Vec2& g) const {
  const double l = fullLength();
  ElemVec f = ElemVec::Zero();
  f.segment<2>(0) = 0.5 * rhoA_ * l * g;
  f.segment<2>(3) = 0.5 * rhoA_ * l * g;
  if (!shear_) {
    // Transverse load q of the Hermite cubic: end moments +-q l^2/12.
    const double q = rhoA_ * (-sin_ * g.x() + cos_ * g.y());
    f(2) = q * l * l / 12.0;
    f(5) = -q * l * l / 12.0;
  }
  return f;
}

// ------------------------------------------------------------ restart files

void LinearFrame::writeState(std::ostream& out) const {
  using namespace checkpoint;
  for (int n : nodes_) put(out, n);
  put(out, materialNumber_);
  putBool(out, shear_);
  for (double x : {length_, cos_, sin_, ea_, ga_, ei_, rhoA_, damping_.coefficient()}) put(out, x);
  putFixed(out, stiffness_);
  putFixed(out, mass_);
  for (const Report* r : {&trial_, &committed_})
    for (double x : {r->energy, r->forces.N, r->forces.V, r->forces.M}) put(out, x);
  putFixed(out, d0_);
  for (double o : rigid_.offsets()) put(out, o);
}

void LinearFrame::readState(std::istream& in) {
  using namespace checkpoint;
  for (int& n : nodes_) n = get<int>(in);
  materialNumber_ = get<int>(in);
  shear_ = getBool(in);
  for (double* x : {&length_, &cos_, &sin_, &ea_, &ga_, &ei_, &rhoA_}) *x = get<double>(in);
  damping_ = SectionDamping(get<double>(in));
  getFixed(in, stiffness_);
  getFixed(in, mass_);
  for (Report* r : {&trial_, &committed_})
    for (double* x : {&r->energy, &r->forces.N, &r->forces.V, &r->forces.M}) *x = get<double>(in);
  getFixed(in, d0_);
  const double o1 = get<double>(in), o2 = get<double>(in);
  rigid_ = RigidEnds(Vec2::Zero(), (length_ + o1 + o2) * Vec2(cos_, sin_), o1, o2);
}

// ------------------------------------------------------------ material change

Status LinearFrame::setMaterial(const MaterialSet& mat, const ElemVec& d) {
  if (mat.kinematics != Kinematics::Small)
    return Status::failure(
        "the element has small (SMALl) kinematics; it cannot change to FINIte here (HINGe2joint "
        "switches elements to finite kinematics)");
  if (mat.hardening || mat.softening)
    return Status::failure(
        "the element is an elastic frame (its set had no HARDening or SOFTening when it was "
        "built); the laws cannot be added to it");
  const LinearFrame fresh(mat, nodes_, Vec2::Zero(), fullLength() * Vec2(cos_, sin_),
                          rigid_.offsets());
  if (!(fresh.ea_ > 0) || !(fresh.ei_ > 0) || (fresh.shear_ && !(fresh.ga_ > 0)))
    return Status::failure("the new section stiffnesses must be positive");
  // Solve K_new x = f (the old end forces, which are self-equilibrated) for the
  // x without rigid-body part: K_new plus a multiple of the projector onto the
  // rigid-body modes (two translations and the rotation about the midpoint,
  // mutually orthogonal) is regular and maps that x to f.
  const ElemVec f = stiffness_ * (d - d0_);
  const double h = 0.5 * fullLength();  // the modes of the nodes' motion
  ElemVec tx, ty, rz;
  tx << 1, 0, 0, 1, 0, 0;
  ty << 0, 1, 0, 0, 1, 0;
  rz << h * sin_, -h * cos_, 1, -h * sin_, h * cos_, 1;
  ElemMat a = fresh.stiffness_;
  const double scale = fresh.stiffness_.diagonal().maxCoeff();
  for (const ElemVec* v : {&tx, &ty, &rz})
    a += scale * (*v / v->norm()) * (*v / v->norm()).transpose();
  const ElemVec x = a.partialPivLu().solve(f);
  if (!x.allFinite()) return Status::failure("the new stiffness matrix is singular");
  shear_ = fresh.shear_;
  ea_ = fresh.ea_;
  ga_ = fresh.ga_;
  ei_ = fresh.ei_;
  rhoA_ = fresh.rhoA_;
  damping_ = fresh.damping_;
  stiffness_ = fresh.stiffness_;
  mass_ = fresh.mass_;
  d0_ = d - x;
  return Status::success();
}

}  // namespace c2d
