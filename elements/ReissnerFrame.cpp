#include "elements/ReissnerFrame.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>

#include "materials/RcSection.h"

namespace c2d {

namespace {


using Mat2 = Eigen::Matrix2d;

// Counterclockwise quarter turn: d Lambda(psi)/d psi = W Lambda(psi).
const Mat2 kW = (Mat2() << 0, -1, 1, 0).finished();

Mat2 rot(double psi) {
  const double c = std::cos(psi), s = std::sin(psi);
  return (Mat2() << c, -s, s, c).finished();
}

// sin(x)/x and its derivative; series below |x| = 0.1 where the closed forms
// lose digits to cancellation (truncation error there is below 1e-19).
double sinc(double x) {
  if (std::abs(x) < 0.1) {
    const double x2 = x * x;
    return 1 - x2 / 6 * (1 - x2 / 20 * (1 - x2 / 42 * (1 - x2 / 72 * (1 - x2 / 110))));
  }
  return std::sin(x) / x;
}

double sincPrime(double x) {
  if (std::abs(x) < 0.1) {
    // d/dx sum_k (-1)^k x^{2k}/(2k+1)!
    const double x2 = x * x;
    return -x / 3 * (1 - x2 / 10 * (1 - x2 / 28 * (1 - x2 / 54 * (1 - x2 / 88))));
  }
  return (x * std::cos(x) - std::sin(x)) / (x * x);
}

// Node a of the element: translation dofs start at 3a, rotation at 3a + 2;
// sign of the node in phi' = (phi_2 - phi_1)/l.
constexpr int uDof(int a) { return kNodeDofs * a; }
constexpr int thDof(int a) { return kNodeDofs * a + 2; }
constexpr double nodeSign(int a) { return a == 0 ? -1.0 : 1.0; }

// The strain operators of this element have the form
//   B = [-P c P c] (2 x 6; P 2 x 2, c a column shared by both rotations),
//   bk = [0 0 -1/l 0 0 1/l] (curvature),
// so products with them are written out blockwise.

// f = l (B^T n + bk^T m).
void strainOperatorForce(double l, const Mat2& p, const Vec2& c, const Vec2& n, double m,
                         ElemVec& f) {
  const Vec2 pn = l * (p.transpose() * n);
  const double cn = l * c.dot(n);
  for (int a = 0; a < 2; ++a) {
    f.segment<2>(uDof(a)) = nodeSign(a) * pn;
    f(thDof(a)) = cn + nodeSign(a) * m;
  }
}

// k = w l (B^T C B1 + g EI bk^T bk), C = diag(EA, GA), B1 = [-P1 c1 P1 c1],
// B = [-P c_1 P c_2] (the rotation columns of the test operator may differ per
// node) and g the factor of the test curvature.
void materialTangent(double l, double w, const Mat2& p, const std::array<Vec2, 2>& c, double g,
                     const Mat2& p1, const Vec2& c1, double ea, double ga, double ei, ElemMat& k) {
  const double wl = w * l;
  const Mat2 cp1 = Vec2(ea, ga).asDiagonal() * p1;
  const Vec2 cc1(ea * c1.x(), ga * c1.y());
  const Mat2 uu = wl * (p.transpose() * cp1);
  const Vec2 ut = wl * (p.transpose() * cc1);
  const double kk = w * g * ei / l;
  for (int a = 0; a < 2; ++a) {
    const double sa = nodeSign(a);
    const Vec2 tu = wl * (cp1.transpose() * c[a]);
    const double tt = wl * c[a].dot(cc1);
    for (int b = 0; b < 2; ++b) {
      const double sb = nodeSign(b);
      k.block<2, 2>(uDof(a), uDof(b)) = (sa * sb) * uu;
      k.block<2, 1>(uDof(a), thDof(b)) = sa * ut;
      k.block<1, 2>(thDof(a), uDof(b)) = sb * tu.transpose();
      k(thDof(a), thDof(b)) = tt + sa * sb * kk;
    }
  }
}

}  // namespace

ReissnerFrame::ReissnerFrame(const MaterialSet& mat, const std::array<int, 2>& nodes,
                             const Vec2& x1, const Vec2& x2, const std::array<double, 2>& offsets)
    : nodes_(nodes),
      materialNumber_(mat.number),
      rigid_(x1, x2, offsets[0], offsets[1]),
      x1_(rigid_.face(0, x1)),
      x2_(rigid_.face(1, x2)),
      length_((x2_ - x1_).norm()),
      beta0_(std::atan2(x2.y() - x1.y(), x2.x() - x1.x())),
      ea_(mat.EA()),
      ga_(mat.GA()),
      ei_(mat.EI()),
      rhoA_(mat.rhoA()),
      law_(mat),
      damping_(mat.dampingA1) {
  assert(length_ > 0 && "element of zero length");
  if (mat.rc) axial_ = mat.rc->axialCapacity();
  rc_ = mat.rc;
  // Rotation is additive in 2D: the kinetic energy is quadratic in the nodal
  // velocities, so the mass matrix is constant (linear shape functions). The
  // rigid zones' mass belongs to the joint region: the full length's.
  const double rhoI = mat.rhoI();
  mass_.setZero();
  for (int i = 0; i < kNodeDofs; ++i) {
    const double mu = (i < 2 ? rhoA_ : rhoI) * fullLength();
    if (mat.mass == MassType::Lumped) {
      mass_(i, i) = mass_(i + 3, i + 3) = mu / 2;
    } else {
      mass_(i, i) = mass_(i + 3, i + 3) = mu / 3;
      mass_(i, i + 3) = mass_(i + 3, i) = mu / 6;
    }
  }
}

Vec3 ReissnerFrame::strains(const ElemVec& d) const {
  return faceStrains(rigid_.any() ? rigid_.faceDisplacement(d) : d);
}

Vec3 ReissnerFrame::faceStrains(const ElemVec& d) const {
  const Vec2 g = (x2_ + d.segment<2>(3) - x1_ - d.segment<2>(0)) / length_;
  const Vec2 e = rot(beta0_ + 0.5 * (d(2) + d(5))).transpose() * g - Vec2::UnitX();
  return {e.x(), e.y(), (d(5) - d(2)) / length_};
}

double ReissnerFrame::energy(const ElemVec& d) const {
  const Vec3 e = strains(d) - e0_;
  return 0.5 * length_ * (ea_ * e(0) * e(0) + ga_ * e(1) * e(1) + ei_ * e(2) * e(2));
}

// Internal force grad W(d) and its (symmetric) derivative for the bending
// moment m and its tangent kt = dm/dK at d; returns E(d).
Vec3 ReissnerFrame::staticForce(const ElemVec& d, double m, double kt, const Damper& damper,
                                bool wantTangent, ElemVec& f, ElemMat& k, const Coupling* cp) const {
  const double l = length_;
  const Vec2 g = (x2_ + d.segment<2>(3) - x1_ - d.segment<2>(0)) / l;
  const Mat2 lam = rot(beta0_ + 0.5 * (d(2) + d(5)));
  const Vec2 h = lam.transpose() * g;  // Lambda^T phi'
  const Vec3 e(h.x() - 1, h.y(), (d(5) - d(2)) / l);
  const double df = damper.f;
  Vec2 n(ea_ * (e(0) - e0_(0) + df * (e(0) - damper.eN(0))),
         ga_ * (e(1) - e0_(1) + df * (e(1) - damper.eN(1))));
  if (cp && cp->axial) n.x() = cp->n;

  // dE/dd: dh/dphi' = Lambda^T, dh/dpsi = -W h, dpsi/dtheta_a = 1/2.
  const Mat2 p = lam.transpose() / l;
  const Vec2 c = -0.5 * kW * h;
  strainOperatorForce(l, p, c, n, m, f);
  if (!wantTangent) return e;

  materialTangent(l, 1.0, p, {c, c}, 1.0, p, c, cp && cp->axial ? cp->ea : (1 + df) * ea_,
                  (1 + df) * ga_, kt, k);
  if (cp && cp->moment)
    for (int a = 0; a < 2; ++a) k.row(thDof(a)) += nodeSign(a) * cp->dm.transpose();
  // Geometric part n . d(b_j)/d(d_k).
  const Vec2 q = lam * kW.transpose() * n;  // q_i = n . (W Lambda^T e_i)
  const double nh = n.dot(h);
  for (int a = 0; a < 2; ++a) {
    for (int bn = 0; bn < 2; ++bn) {
      k(thDof(a), thDof(bn)) += -0.25 * l * nh;
      for (int i = 0; i < 2; ++i) {
        const double gk = -0.5 * nodeSign(a) * q(i);
        k(uDof(a) + i, thDof(bn)) += gk;
        k(thDof(bn), uDof(a) + i) += gk;
      }
    }
  }
  return e;
}

// Energy and momentum conserving/decaying internal force between dn and d, and
// its exact derivative with respect to d; returns E(d). With
// Lambda_{n+1} = Lambda_mid R(x), Lambda_n = Lambda_mid R(-x), R(x) = cos x + sin x W,
// x = Delta/4 (Delta = theta_1 + theta_2 increments, the midpoint rotation's
// increment twice), and g = phi':
//   E_{n+1} - E_n = cos x Lambda_mid^T (g_{n+1} - g_n) - 2 sin x W a_M,
//   a_M = Lambda_mid^T g_mid,  K_{n+1} - K_n = (dtheta_2 - dtheta_1)/l.
// The nodal rotations pair with their Cayley increments c_a = 2 tan(dtheta_a/2)
// (core/StepRule.h). The translations carry f_2 = -f_1 = cos x Lambda_mid n; the
// nodal moments are fixed by two conditions: their work sum_a m_a c_a is the
// strain work n.(2 sin x (-W a_M)) l + M (dtheta_2 - dtheta_1) (energy), and their
// sum balances the moment of the end forces about the mid-point configuration,
// -l g_mid x f_2 = cos x S, S = -l n.(W a_M) (angular momentum). With
// y = (dtheta_2 - dtheta_1)/4, so that dtheta_a = 2(x -+ y):
//   m_a = S (cos x -+ sin x tan y)/2 -+ M g,  g = (cos^2 x - sin^2 y) / sinc(2y),
// in closed form without cancellation (tan(x - y) + tan(x + y) and their
// difference share the denominator cos^2 x - sin^2 y).
// m: the algorithmic bending moment, kt: dm/dK_{n+1} / (1/2 + alpha).
Vec3 ReissnerFrame::midPointForce(const ElemVec& d, const ElemVec& dn, double alpha, double m,
                                  double kt, bool wantTangent, ElemVec& f, ElemMat& k,
                                  std::array<double, 2>& halfTan, const Coupling* cp) const {
  const double l = length_;
  const Vec2 g1 = (x2_ + d.segment<2>(3) - x1_ - d.segment<2>(0)) / l;
  const Vec2 g0 = (x2_ + dn.segment<2>(3) - x1_ - dn.segment<2>(0)) / l;
  const double th1 = 0.5 * (d(2) + d(5)), th0 = 0.5 * (dn(2) + dn(5));
  const double x = 0.5 * (th1 - th0);
  const double y = 0.25 * ((d(5) - dn(5)) - (d(2) - dn(2)));
  // Lambda_mid = Lambda_n R(x): Lambda_n = rot(beta0 + th0) once per step.
  if (const double angleN = beta0_ + th0; angleN != meanAngleN_) {
    lamN_ = rot(angleN);
    meanAngleN_ = angleN;
  }
  const Mat2 rx = rot(x);
  const double cx = rx(0, 0), sx = rx(1, 0);
  const Mat2 lamM = lamN_ * rx;
  const Vec2 a1 = lamM.transpose() * g1, a0 = lamM.transpose() * g0;
  const Vec2 aM = 0.5 * (a1 + a0);
  const Vec2 h1 = rx.transpose() * a1;  // Lambda_{n+1}^T g1
  const Vec2 h0 = rx * a0;              // Lambda_n^T g0

  const Vec3 e1(h1.x() - 1, h1.y(), (d(5) - d(2)) / l);
  const Vec3 e0(h0.x() - 1, h0.y(), (dn(5) - dn(2)) / l);
  const Vec3 eAlg = (0.5 + alpha) * e1 + (0.5 - alpha) * e0 - e0_;
  Vec2 n(ea_ * eAlg(0), ga_ * eAlg(1));
  if (cp && cp->axial) n.x() = cp->n;

  const Vec2 lamN = lamM * n;  // Lambda_mid n
  const Vec2 wAM = kW * aM;
  const double S = -l * n.dot(wAM);
  // One sine-cosine pair for y: tan y, sin 2y, cos 2y and sinc(2y) from it.
  const double sy = std::sin(y), cy = std::cos(y), ty = sy / cy;
  const double s2y = 2 * sy * cy, c2y = cy * cy - sy * sy;
  const double sc2 = std::abs(2 * y) < 0.1 ? sinc(2 * y) : s2y / (2 * y);
  const double g = (cx * cx - sy * sy) / sc2;
  const std::array<double, 2> h = {0.5 * (cx + sx * ty), 0.5 * (cx - sx * ty)};
  // dtheta_a / 2 = x -+ y.
  halfTan = {(sx * cy - cx * sy) / (cx * cy + sx * sy), (sx * cy + cx * sy) / (cx * cy - sx * sy)};
  for (int a = 0; a < 2; ++a) {
    f.segment<2>(uDof(a)) = (nodeSign(a) * cx) * lamN;
    f(thDof(a)) = S * h[a] + nodeSign(a) * m * g;
  }
  if (!wantTangent) return e1;

  // Material part: dE_{n+1}/dd, the consistent operator at d (Lambda_{n+1} = Lambda_mid R(x)),
  // tested with the rows of the force above.
  const Mat2 p = (cx / l) * lamM.transpose();
  const Mat2 p1 = (lamM * rx).transpose() / l;
  const Vec2 c1 = -0.5 * kW * h1;
  materialTangent(l, 0.5 + alpha, p, {-h[0] * wAM, -h[1] * wAM}, g, p1, c1,
                  cp && cp->axial ? cp->ea : ea_, ga_, kt, k);
  if (cp && cp->moment)
    for (int a = 0; a < 2; ++a) k.row(thDof(a)) += (nodeSign(a) * g) * cp->dm.transpose();

  // Geometric part: x, y, psi_mid and g_mid move with d: dx/dtheta_a = dpsi_mid/dtheta_a = 1/4,
  // dy/dtheta_a = sign_a/4, dg_mid/du_a = sign_a/(2l); d(Lambda_mid^T)/dpsi = -W Lambda_mid^T.
  const Vec2 q = lamM * kW.transpose() * n;  // q_i = n . (W Lambda_mid^T e_i)
  const double dSdTh = -0.25 * l * n.dot(aM);
  const double dgdx = -2 * cx * sx / sc2;
  const double sc2Prime =
      std::abs(2 * y) < 0.1 ? sincPrime(2 * y) : (2 * y * c2y - s2y) / (4 * y * y);
  const double dgdy = -s2y / sc2 - 2 * g * sc2Prime / sc2;
  for (int a = 0; a < 2; ++a) {
    const double sa = nodeSign(a);
    const double dhdx = 0.5 * (-sx - sa * cx * ty), dhdy = -0.5 * sa * sx * (1 + ty * ty);
    for (int b = 0; b < 2; ++b) {
      const double sb = nodeSign(b);
      k(thDof(a), thDof(b)) +=
          h[a] * dSdTh + 0.25 * (S * (dhdx + sb * dhdy) + sa * m * (dgdx + sb * dgdy));
      for (int i = 0; i < 2; ++i) {
        k(uDof(a) + i, thDof(b)) += 0.25 * sa * (-sx * lamN(i) - cx * q(i));
        k(thDof(a), uDof(b) + i) += -0.5 * sb * h[a] * q(i);
      }
    }
  }
  return e1;
}

ElemVec ReissnerFrame::axialStrainGradient(const ElemVec& d) const {  // d: the faces'
  // Sigma = (Lambda^T phi')_1 - 1: dSigma/du_a = -+(cos psi, sin psi)/l, dSigma/dtheta_a = Gamma/2.
  const double psi = beta0_ + 0.5 * (d(2) + d(5));
  const Vec2 t(std::cos(psi) / length_, std::sin(psi) / length_);
  const double half = 0.5 * faceStrains(d)(1);
  ElemVec g;
  g << -t.x(), -t.y(), half, t.x(), t.y(), half;
  return g;
}

// What one evaluation's section laws give: the axial force N_{n+1} (laws that
// follow it), the bending response at the curvatures of d and d_n, and the
// section dashpot's factor f with its bending and axial parts.
struct ReissnerFrame::StepResponse {
  bool coupled = false;
  double N1 = 0;
  HingedBendingResponse bend;
  double m1 = 0, kappa1 = 0, kappaN = 0;
  double f = 0;
  SectionDamping::Bending md, nd;
};

double ReissnerFrame::axialResponse(const ElementKinematics& fk) {
  const double sigma = faceStrains(fk.d)(0) - e0_(0);
  double N1 = ea_ * sigma;
  axialTangent_ = ea_;
  if (axial_) {
    const AxialResponse a = axial_->returnMap(committed_.axial, sigma);
    N1 = a.N;
    axialTangent_ = a.tangent;
    trial_.axial = a.state;
  }
  axialGradient_ = axialTangent_ * axialStrainGradient(fk.d);
  return N1;
}

Status ReissnerFrame::bendingResponse(const ElementKinematics& fk, const StepRule& rule,
                                      double openSign, StepResponse& sr) const {
  const HingedBendingState& from = committed_.section;
  // Bending: the curvature K = (theta2 - theta1)/l is linear in d.
  sr.kappa1 = (fk.d(5) - fk.d(2)) / length_ - e0_(2);
  if (Status st = law_.respond(sr.kappa1, length_, from, openSign, sr.bend, sr.N1, held_); !st)
    return st;
  sr.m1 = sr.bend.state.M;
  sr.kappaN = (fk.dn(5) - fk.dn(2)) / length_ - e0_(2);
  // The section's dashpot (materials/SectionDamping.h): f = a1/h times the
  // strains' change over the step, in bending the elastic curvature's, axially
  // (a bounded axial force) the elastic strain's.
  sr.f = damping_.factor(rule);
  if (sr.f > 0) {
    sr.md = law_.isElastic() ? SectionDamping::elasticBending(sr.f, law_.EI(), sr.kappa1 - sr.kappaN)
                             : SectionDamping::bending(sr.f, law_.EI(), sr.m1 - from.M,
                                                       sr.kappa1 - sr.kappaN, sr.bend.tangent);
    if (axial_)
      sr.nd = axial_->damping(sr.f, committed_.forces.N, sr.N1,
                              faceStrains(fk.d)(0) - faceStrains(fk.dn)(0),
                              trial_.axial.ep - committed_.axial.ep, axialTangent_);
  }
  return Status::success();
}

Vec3 ReissnerFrame::midPointResultants(const ElementKinematics& fk, const StepRule& rule,
                                       const StepResponse& sr, bool wantTangent,
                                       ElemVec& residual, ElemMat& tangent,
                                       std::array<double, 2>& halfTan) const {
  // Resultants at the alpha-weighted point: for bending the weighted moments
  // of the committed and the trial state; an elastic section's moment at t_n
  // is that of the curvature at d_n. The dashpot weighs the strains' change
  // by f more (alpha + f); its moment is added to the weighted one.
  const double f = sr.f;
  const double w = 0.5 + rule.alpha, wd = w + f;
  if (law_.isElastic())
    return midPointForce(
        fk.d, fk.dn, rule.alpha + f, w * sr.m1 + (1 - w) * law_.EI() * sr.kappaN + sr.md.m,
        f > 0 ? (w * sr.bend.tangent + sr.md.tangent) / wd : sr.bend.tangent, wantTangent,
        residual, tangent, halfTan);
  // Inelastic: a moment whose work never exceeds the stored energy's change.
  const HingedBendingState& from = committed_.section;
  const auto mm =
      law_.midPointMoment(from, sr.kappaN, sr.bend.state, sr.kappa1, sr.bend.tangent, length_, w);
  Coupling cp;
  if (sr.coupled) {
    cp.moment = sr.bend.dN != 0;
    cp.dm = ((mm.dM1 + sr.md.dM1) * sr.bend.dN) * axialGradient_;
    if (axial_) {
      const AxialCapacity::MidPoint mp = axial_->midPoint(
          committed_.forces.N, sr.N1, faceStrains(fk.dn)(0) - e0_(0), faceStrains(fk.d)(0) - e0_(0),
          axialTangent_, trial_.axial.ep - committed_.axial.ep, w, HingedBending::kMidPointRatio);
      cp.axial = true;
      cp.n = mp.n + sr.nd.m;
      cp.ea = (mp.tangent + sr.nd.tangent) / wd;
    }
  }
  return midPointForce(fk.d, fk.dn, rule.alpha + f, mm.m + sr.md.m,
                       (mm.tangent + sr.md.tangent) / wd, wantTangent, residual, tangent, halfTan,
                       sr.coupled ? &cp : nullptr);
}

Vec3 ReissnerFrame::staticResultants(const ElementKinematics& fk, const StepResponse& sr,
                                     bool wantTangent, ElemVec& residual,
                                     ElemMat& tangent) const {
  Coupling cp;
  if (sr.coupled) {
    cp.axial = axial_.has_value();
    cp.n = sr.N1 + sr.nd.m;
    cp.ea = axialTangent_ + sr.nd.tangent;
    cp.moment = sr.bend.dN != 0;
    cp.dm = ((1 + sr.md.dM1) * sr.bend.dN) * axialGradient_;
  }
  Damper damper;
  if (sr.f > 0) damper = {sr.f, faceStrains(fk.dn)};
  return staticForce(fk.d, sr.m1 + sr.md.m, sr.bend.tangent + sr.md.tangent, damper, wantTangent,
                     residual, tangent, sr.coupled ? &cp : nullptr);
}

void ReissnerFrame::storeTrial(const Vec3& strain, const StepResponse& sr,
                               const std::array<double, 2>& ends) {
  const HingedBendingState& from = committed_.section;
  const double N1 = sr.N1, m1 = sr.m1;
  const Vec3 e = strain - e0_;
  trial_.section = sr.bend.state;
  for (int a = 0; a < 2; ++a)
    if (from.endHinge[a] == 0) trial_.section.endHinge[a] = ends[a];
  trial_.forces = {axial_ ? N1 : ea_ * e(0), ga_ * e(1), m1};
  if (law_.site() == HingeSite::Ends) {
    // End moments M -+ S/2 from the element's equilibrium (material resultants at n+1).
    const double S = length_ * (trial_.forces.N * strain(1) - trial_.forces.V * (1 + strain(0)));
    trial_.section.endMoment = {m1 - 0.5 * S, m1 + 0.5 * S};
  }
  const double axialEnergy = axial_ ? 2 * axial_->energyDensity(N1) : ea_ * e(0) * e(0);
  trial_.energy =
      0.5 * length_ * (axialEnergy + ga_ * e(1) * e(1)) + length_ * law_.energyDensity(sr.bend.state);
}

Status ReissnerFrame::evaluate(const ElementKinematics& kin, const StepRule& rule, bool wantTangent,
                               ElemVec& residual, ElemMat& tangent) {
  if (!rule.rotationsInRange(kin.d - kin.dn)) return Status::failure(StepRule::kRotationRangeMessage);
  // Rigid end zones: the law acts on the flexible part, driven by the faces.
  ElementKinematics faces;
  if (rigid_.any()) {
    faces.d = rigid_.faceDisplacement(kin.d);
    faces.dn = rigid_.faceDisplacement(kin.dn);
  }
  const ElementKinematics& fk = rigid_.any() ? faces : kin;
  const HingedBendingState& from = committed_.section;
  const double openSign =
      !from.hingeActive && trial_.section.hingeActive ? trial_.section.hingeSign : 0.0;
  // Laws that follow the axial force: N_{n+1} first (the material one).
  StepResponse sr;
  sr.coupled = axial_.has_value() || law_.capacity() != nullptr;
  if (sr.coupled) sr.N1 = axialResponse(fk);
  const std::array<double, 2> ends = trial_.section.endHinge;  // opened in this trial
  if (Status st = bendingResponse(fk, rule, openSign, sr); !st) return st;
  Vec3 strain;
  std::array<double, 2> halfTan{};
  const std::array<double, 2>* halfTanAt = nullptr;
  if (rule.scheme == Scheme::MidPoint) {
    halfTanAt = &halfTan;
    strain = midPointResultants(fk, rule, sr, wantTangent, residual, tangent, halfTan);
  } else {
    strain = staticResultants(fk, sr, wantTangent, residual, tangent);
  }
  if (rigid_.any()) {
    rigid_.toNodes(kin.d, rule.scheme == Scheme::MidPoint ? &kin.dn : nullptr, residual,
                   wantTangent ? &tangent : nullptr);
    if (sr.coupled) axialGradient_ = rigid_.jacobian(kin.d).transpose() * axialGradient_;
  }
  if (rule.dynamic())
    rule.addInertia(mass_, kin.d - kin.dn, kin.vn, kin.an, residual, wantTangent ? &tangent : nullptr,
                    halfTanAt);
  if (!residual.allFinite() || (wantTangent && !tangent.allFinite()))
    return Status::failure("frame-reissner element: non-finite residual or tangent");
  storeTrial(strain, sr, ends);
  return Status::success();
}

double ReissnerFrame::fractureDemand() const {
  if (!axial_ || trial_.fracture != Parting::Whole) return 0;
  return axial_->fractureDemand(axial_->strain(trial_.forces.N, trial_.axial));
}

double ReissnerFrame::bendingDemand() const { return held_ ? 0.0 : law_.demand(trial_.section); }

double ReissnerFrame::shearDemand() const {
  if (!rc_ || trial_.fracture != Parting::Whole) return 0;
  return rc_->shear().demand(trial_.forces.V, trial_.forces.N);
}

double ReissnerFrame::shearCapacity() const {
  return rc_ ? rc_->shearCapacity(trial_.forces.N) : 0.0;
}

double ReissnerFrame::hingeDemand() const {
  return std::max({bendingDemand(), fractureDemand(), shearDemand()});
}

void ReissnerFrame::activateHinge() {
  const double fracture = fractureDemand(), shear = shearDemand();
  if (std::max(fracture, shear) > bendingDemand())
    trial_.fracture = shear > fracture ? Parting::Sheared : Parting::BarsFractured;
  else if (!held_)
    law_.open(trial_.section);
}

int ReissnerFrame::earlyEnd() const {
  return bendingDemand() >= std::max(fractureDemand(), shearDemand())
             ? law_.criticalEnd(trial_.section)
             : -1;
}

void ReissnerFrame::activateHingeAt(int end) { law_.openEnd(trial_.section, end); }

HingeInfo ReissnerFrame::hinge() const {
  HingeInfo h = law_.info(trial_.section);
  h.fracture =
      trial_.fracture == Parting::BarsFractured || trial_.fracture == Parting::Sheared;
  h.shear = trial_.fracture == Parting::Sheared;
  return h;
}

void ReissnerFrame::setSection(const HingedBendingState& s) { trial_.section = committed_.section = s; }

ElemVec ReissnerFrame::bodyLoad(const Vec2& g) const {
  ElemVec f = ElemVec::Zero();
  f.segment<2>(0) = 0.5 * rhoA_ * fullLength() * g;
  f.segment<2>(3) = 0.5 * rhoA_ * fullLength() * g;
  return f;
}

// ------------------------------------------------------------ restart files

void ReissnerFrame::writeState(std::ostream& out) const {
  using namespace checkpoint;
  for (int n : nodes_) put(out, n);
  put(out, materialNumber_);
  putFixed(out, x1_);
  putFixed(out, x2_);
  for (double x : {length_, beta0_, ea_, ga_, ei_, rhoA_, damping_.coefficient()}) put(out, x);
  putFixed(out, e0_);
  putFixed(out, mass_);
  // The material set may have hinge laws that this element dropped (HINGE2JOINT).
  putBool(out, law_.isElastic());
  for (const Report* r : {&trial_, &committed_}) {
    for (double x : {r->energy, r->forces.N, r->forces.V, r->forces.M, r->axial.ep, r->axial.xi})
      put(out, x);
    put(out, static_cast<int>(r->fracture));
    putSection(out, r->section);
  }
  put(out, axialTangent_);
  putFixed(out, axialGradient_);
  for (double o : rigid_.offsets()) put(out, o);
}

void ReissnerFrame::readState(std::istream& in) {
  using namespace checkpoint;
  for (int& n : nodes_) n = get<int>(in);
  materialNumber_ = get<int>(in);
  getFixed(in, x1_);
  getFixed(in, x2_);
  for (double* x : {&length_, &beta0_, &ea_, &ga_, &ei_, &rhoA_}) *x = get<double>(in);
  damping_ = SectionDamping(get<double>(in));
  getFixed(in, e0_);
  getFixed(in, mass_);
  if (getBool(in)) {
    law_ = HingedBending(BilinearHardening::elastic(ei_), std::nullopt);
    axial_.reset();
    rc_.reset();
  }
  for (Report* r : {&trial_, &committed_}) {
    for (double* x : {&r->energy, &r->forces.N, &r->forces.V, &r->forces.M, &r->axial.ep,
                      &r->axial.xi})
      *x = get<double>(in);
    r->fracture = getParting(in);
    r->section = getSection(in);
  }
  axialTangent_ = get<double>(in);
  getFixed(in, axialGradient_);
  const double o1 = get<double>(in), o2 = get<double>(in);
  const Vec2 t = (x2_ - x1_) / length_;
  rigid_ = RigidEnds(x1_ - o1 * t, x2_ + o2 * t, o1, o2);
}

// ------------------------------------------------------------ material change

Status ReissnerFrame::setMaterial(const MaterialSet& mat, const ElemVec& d) {
  const ReissnerFrame fresh(mat, nodes_, x1_ - rigid_.arm(0), x2_ - rigid_.arm(1), rigid_.offsets());
  const Vec3 c = fresh.sectionStiffness();
  if (!(c.array() > 0).all())
    return Status::failure("the new section stiffnesses EA, GA, EI must be positive");
  const Vec3 e = strains(d);
  const HingedBendingState& section = committed_.section;
  const Vec2 nv(ea_ * (e(0) - e0_(0)), ga_ * (e(1) - e0_(1)));
  // An element whose laws HINGE2JOINT dropped stays elastic (with the new EI).
  HingedBending law = law_.isElastic() ? HingedBending(BilinearHardening::elastic(c(2)), std::nullopt)
                                       : fresh.law_;
  if (law.hasHinge() && !section.hingeActive && std::abs(section.M) > law.softening()->Mu() * (1 + 1e-9))
    return Status::failure("its moment is above the new Mu (the hinge would open past its capacity)");
  if (section.hingeActive && !law.hasHinge())
    return Status::failure("its softening hinge is active: the SOFTening law cannot be removed");
  ea_ = fresh.ea_;
  ga_ = fresh.ga_;
  ei_ = fresh.ei_;
  rhoA_ = fresh.rhoA_;
  damping_ = fresh.damping_;
  mass_ = fresh.mass_;
  law_ = law;
  const double alpha = section.hingeActive ? section.jump.alpha / length_ : 0.0;
  e0_ = Vec3(e(0) - nv.x() / c(0), e(1) - nv.y() / c(1),
             e(2) - section.bulk.kp - alpha - section.M / c(2));
  return Status::success();
}

}  // namespace c2d
