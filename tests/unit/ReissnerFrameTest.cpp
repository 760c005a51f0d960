// ReissnerFrame: finite rigid motions, tangents vs finite differences for every
// scheme, symmetry, the mid-point energy identity, the link to the linear
// Timoshenko element, and the discrete-exact roll-up of verification.md V1.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "elements/LinearFrame.h"
#include "elements/ReissnerFrame.h"
#include "tests/unit/ElementTestSupport.h"

namespace c2d {
namespace {

constexpr double kPi = std::numbers::pi;

MaterialSet reissnerMaterial(MassType mass = MassType::Consistent) {
  return test::resultantMaterial(Kinematics::Finite, true, mass);
}


// A deformed state: a large rigid rotation w plus a random perturbation.
ElemVec deformedState(std::mt19937& gen, const Vec2& x1, const Vec2& x2, double w) {
  return test::rigidMotion(x1, x2, w, Vec2(0.2, 0.1), Vec2(0.3, -0.4)) + test::randomVec(gen, 0.08);
}

StepRule makeRule(Scheme scheme, double alpha = 0) { return test::stepRule(scheme, alpha); }

TEST(ReissnerFrameRigidBody, FiniteRigidMotionsGiveZeroResidual) {
  const Vec2 x1(1.0, -0.5), x2(2.2, 1.1);
  ReissnerFrame e(reissnerMaterial(), {0, 1}, x1, x2);
  test::expectRigidMotionsGiveZeroResidual(e, x1, x2);
}

TEST(ReissnerFrameTangent, MatchesFiniteDifferencesForEveryScheme) {
  std::mt19937 gen(2024);
  const Vec2 x1(0.0, 0.0), x2(1.6, -1.2);
  for (MassType mt : {MassType::Consistent, MassType::Lumped}) {
    ReissnerFrame e(reissnerMaterial(mt), {0, 1}, x1, x2);
    const StepRule rules[] = {makeRule(Scheme::Static), makeRule(Scheme::Newmark),
                              makeRule(Scheme::MidPoint, 0.0), makeRule(Scheme::MidPoint, 0.2)};
    // (rotation at n+1, rotation at n): far apart, beyond pi, close (series
    // branch of sin(x)/x), and identical mean rotations.
    const std::pair<double, double> rotations[] = {
        {4.0, 2.9}, {-3.6, -2.4}, {10.2, 10.25}, {7.0, 7.0}};
    for (const StepRule& rule : rules) {
      for (auto [w1, w0] : rotations) {
        ElementKinematics kin{deformedState(gen, x1, x2, w1), deformedState(gen, x1, x2, w0),
                              test::randomVec(gen, 1.0), test::randomVec(gen, 10.0)};
        if (w1 == w0) {
          // Same mean rotation exactly: Delta = 0.
          const double m = 0.5 * (kin.d(2) + kin.d(5)) - 0.5 * (kin.dn(2) + kin.dn(5));
          kin.dn(2) += m;
          kin.dn(5) += m;
        }
        ElemVec r;
        ElemMat k;
        ASSERT_TRUE(e.evaluate(kin, rule, true, r, k).ok);
        const ElemMat fd = test::centralDifferenceTangent(e, kin, rule);
        EXPECT_LT((fd - k).cwiseAbs().maxCoeff(), 1e-7 * k.cwiseAbs().maxCoeff())
            << "scheme " << static_cast<int>(rule.scheme) << " alpha " << rule.alpha << " w " << w1
            << ", " << w0;
      }
    }
  }
}

TEST(ReissnerFrameTangent, StaticTangentAndMassAreSymmetric) {
  std::mt19937 gen(5);
  const Vec2 x1(0.3, 0.3), x2(-0.9, 1.4);
  ReissnerFrame e(reissnerMaterial(), {0, 1}, x1, x2);
  for (double w : {0.7, 3.5, -10.0}) {
    const ElemVec d = deformedState(gen, x1, x2, w);
    ElemVec r;
    ElemMat k;
    ASSERT_TRUE(e.evaluate({d, d, d, d}, makeRule(Scheme::Static), true, r, k).ok);
    EXPECT_LT((k - k.transpose()).cwiseAbs().maxCoeff(), 1e-12 * k.cwiseAbs().maxCoeff());
  }
  const ElemMat m = e.mass();
  EXPECT_LT((m - m.transpose()).cwiseAbs().maxCoeff(), 1e-15 * m.cwiseAbs().maxCoeff());
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<ElemMat>(m).eigenvalues().minCoeff(), 0.0);
}

// The tangent at the reference state is the linear one-point Timoshenko stiffness.
TEST(ReissnerFrameTangent, LinearizesToTimoshenkoElement) {
  const Vec2 x1(0.5, 1.0), x2(-0.4, 2.7);
  MaterialSet mat = reissnerMaterial();
  ReissnerFrame e(mat, {0, 1}, x1, x2);
  mat.kinematics = Kinematics::Small;
  LinearFrame lin(mat, {0, 1}, x1, x2);
  const ElemVec z = ElemVec::Zero();
  ElemVec r;
  ElemMat k;
  ASSERT_TRUE(e.evaluate({z, z, z, z}, makeRule(Scheme::Static), true, r, k).ok);
  EXPECT_LT(r.norm(), 1e-12);
  EXPECT_LT((k - lin.stiffness()).cwiseAbs().maxCoeff(), 1e-12 * k.cwiseAbs().maxCoeff());
  EXPECT_LT((e.mass() - lin.mass()).cwiseAbs().maxCoeff(), 1e-15);
}

// r(d - dn).f_int = W(d) - W(dn) + alpha l dE.C.dE, exactly, at any step size (r:
// the rotations' Cayley increments 2 tan(dtheta/2), core/StepRule.h).
TEST(ReissnerFrameMidPoint, EnergyIdentity) {
  std::mt19937 gen(99);
  const Vec2 x1(0.0, 0.0), x2(0.8, 1.5);
  const MaterialSet mat = reissnerMaterial();
  ReissnerFrame e(mat, {0, 1}, x1, x2);
  const Vec3 c(mat.EA(), mat.GA(), mat.EI());
  for (double alpha : {0.0, 0.2}) {
    StepRule rule = makeRule(Scheme::MidPoint, alpha);
    rule.ca = rule.av = rule.aa = 0;  // internal force only
    const std::pair<double, double> rotations[] = {{0.3, 0.1}, {4.0, 2.6}, {12.0, 10.0}};
    for (auto [w1, w0] : rotations) {
      const ElemVec d = deformedState(gen, x1, x2, w1), dn = deformedState(gen, x1, x2, w0);
      ElemVec r;
      ElemMat k;
      ASSERT_TRUE(e.evaluate({d, dn, ElemVec::Zero(), ElemVec::Zero()}, rule, false, r, k).ok);
      const double w = e.energy(d), wn = e.energy(dn);
      // The reported energy comes from the mid-point's rotations: equal to round-off.
      EXPECT_NEAR(e.strainEnergy(), w, 1e-14 * std::abs(w));
      const Vec3 de = e.strains(d) - e.strains(dn);
      const double expected = w - wn + alpha * e.length() * de.dot(c.cwiseProduct(de));
      EXPECT_NEAR(rule.rate(d - dn).dot(r), expected, 1e-12 * (std::abs(w) + std::abs(wn)))
          << "alpha " << alpha << " w " << w1 << ", " << w0;
    }
  }
}

// Net moment about the origin, in the mid-point configuration (positions
// x + (d + dn)/2), of the nodal forces f: the rate at which f changes the
// angular momentum under the mid-point scheme, dJ = -h moment.
double midPointMoment(const Vec2& x1, const Vec2& x2, const ElemVec& d, const ElemVec& dn,
                      const ElemVec& f) {
  const ElemVec m = 0.5 * (d + dn);
  const Vec2 p1 = x1 + m.segment<2>(0), p2 = x2 + m.segment<2>(3);
  auto cross = [](const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); };
  return cross(p1, f.segment<2>(0)) + f(2) + cross(p2, f.segment<2>(3)) + f(5);
}

// The internal force balances forces and moments exactly (linear and angular
// momentum conserved by the mid-point scheme), with large and unequal nodal
// rotation increments, while its work on the Cayley increments is the energy
// change (EnergyIdentity above).
TEST(ReissnerFrameMidPoint, InternalForceHasNoResultantAndNoMoment) {
  std::mt19937 gen(7);
  const Vec2 x1(0.3, -0.2), x2(1.1, 1.3);
  const MaterialSet mat = reissnerMaterial();
  ReissnerFrame e(mat, {0, 1}, x1, x2);
  for (double alpha : {0.0, 0.2}) {
    StepRule rule = makeRule(Scheme::MidPoint, alpha);
    rule.ca = rule.av = rule.aa = 0;  // internal force only
    for (double dw : {1e-7, 0.02, 0.3, 1.2}) {
      const ElemVec dn = deformedState(gen, x1, x2, 2.0);
      ElemVec d = deformedState(gen, x1, x2, 2.0 + dw);
      d(5) += 0.5 * dw;  // the two sections turn by different amounts
      ElemVec f;
      ElemMat k;
      ASSERT_TRUE(e.evaluate({d, dn, ElemVec::Zero(), ElemVec::Zero()}, rule, false, f, k).ok);
      EXPECT_LT((f.segment<2>(0) + f.segment<2>(3)).norm(), 1e-12 * f.norm());
      EXPECT_LT(std::abs(midPointMoment(x1, x2, d, dn, f)), 1e-12 * e.length() * f.norm())
          << "alpha " << alpha << " dw " << dw;
    }
  }
}

// Under the Cayley rule a rigid spin of the mid-point configuration is strain
// free: positions and sections both turn by 2 atan(eps/2) when the increment's
// rate measure is eps r (r the infinitesimal rotation about the origin at the
// mid-point configuration). With additive rotations the sections would turn by
// eps, shear the element, and an energy conserving force could not balance its
// moments (f.dd = dW != 0 but f.r = 0).
TEST(ReissnerFrameMidPoint, CayleySpinOfTheMidPointConfigurationIsStrainFree) {
  const Vec2 x1(1.0, 0.5), x2(2.5, 0.9);
  const MaterialSet mat = reissnerMaterial();
  ReissnerFrame e(mat, {0, 1}, x1, x2);
  StepRule rule = makeRule(Scheme::MidPoint, 0.0);
  rule.ca = rule.av = rule.aa = 0;
  const double eps = 0.4, turn = 2 * std::atan(0.5 * eps);
  const Eigen::Matrix2d w = (Eigen::Matrix2d() << 0, -1, 1, 0).finished();
  const Eigen::Matrix2d cay = (Eigen::Matrix2d::Identity() - 0.5 * eps * w).inverse() *
                              (Eigen::Matrix2d::Identity() + 0.5 * eps * w);
  EXPECT_LT((cay - test::rot(turn)).norm(), 1e-15);
  const ElemVec dn = ElemVec::Zero();  // unstressed reference
  ElemVec d;
  d << cay * x1 - x1, turn, cay * x2 - x2, turn;
  const ElemVec r = rule.rate(d - dn);
  for (int a = 0; a < 2; ++a) {
    const Vec2 x = (a == 0 ? x1 : x2) + 0.5 * d.segment<2>(3 * a);
    EXPECT_LT((r.segment<2>(3 * a) - eps * w * x).norm(), 1e-14);
    EXPECT_NEAR(r(3 * a + 2), eps, 1e-15);
  }
  ElemVec f;
  ElemMat k;
  ASSERT_TRUE(e.evaluate({d, dn, ElemVec::Zero(), ElemVec::Zero()}, rule, false, f, k).ok);
  EXPECT_LT(e.energy(d), 1e-20);
  EXPECT_LT(f.norm(), 1e-9);
}

TEST(ReissnerFrameSection, MaterialResultantsAreFrameInvariant) {
  const MaterialSet mat = reissnerMaterial();
  const Vec2 x1(0, 0), x2(2.0, 0);
  ReissnerFrame e(mat, {0, 1}, x1, x2);
  // Stretch by s, shear by g, bend by k; then a rigid rotation by 3.5 rad.
  const double s = 0.01, g = 0.02, kap = 0.05, l = 2.0;
  ElemVec d;
  d << 0, 0, -0.5 * kap * l, s * l, g * l, 0.5 * kap * l;
  // With psi_m = 0 the midpoint strains are (s, g, kap) exactly.
  for (double w : {0.0, 3.5}) {
    ElemVec dw;
    dw << test::rot(w) * (x1 + d.head<2>()) - x1, d(2) + w, test::rot(w) * (x2 + d.segment<2>(3)) - x2,
        d(5) + w;
    ElemVec r;
    ElemMat k;
    ASSERT_TRUE(e.evaluate({dw, dw, dw, dw}, makeRule(Scheme::Static), false, r, k).ok);
    const SectionForces f = e.sectionForces();
    EXPECT_NEAR(f.N, mat.EA() * s, 1e-9 * mat.EA());
    EXPECT_NEAR(f.V, mat.GA() * g, 1e-9 * mat.GA());
    EXPECT_NEAR(f.M, mat.EI() * kap, 1e-9 * mat.EI());
    EXPECT_NEAR(e.strainEnergy(),
                0.5 * l * (mat.EA() * s * s + mat.GA() * g * g + mat.EI() * kap * kap), 1e-12);
  }
}

TEST(ReissnerFrameMass, RigidMotionKineticEnergyAndBodyLoad) {
  const double l = 1.8, a = 0.9;
  const Vec2 t(std::cos(a), std::sin(a)), n(-t.y(), t.x()), x1(0.4, 0.2), x2 = x1 + l * t;
  const MaterialSet mat = reissnerMaterial();
  ReissnerFrame e(mat, {0, 1}, x1, x2);
  const double rhoA = mat.rhoA(), rhoI = mat.rhoI(), w = 2.3;
  ElemVec v;
  v << -0.5 * l * w * n, w, 0.5 * l * w * n, w;
  EXPECT_NEAR(e.kineticEnergy(v), 0.5 * w * w * (rhoA * l * l * l / 12 + rhoI * l), 1e-12);
  ReissnerFrame lumped(reissnerMaterial(MassType::Lumped), {0, 1}, x1, x2);
  EXPECT_NEAR(lumped.kineticEnergy(v), 0.5 * w * w * (rhoA * l * l * l / 4 + rhoI * l), 1e-12);
  const Vec2 g(0.0, -9.81);
  const ElemVec f = e.bodyLoad(g);
  ElemVec expected;
  expected << 0.5 * rhoA * l * g, 0, 0.5 * rhoA * l * g, 0;
  EXPECT_LT((f - expected).norm(), 1e-14);
}

// Cantilever of n elements along direction `angle`, clamped at the origin,
// end moment m: static Newton with load steps, using the element's residual
// and tangent. Returns the nodal dofs.
struct RollUp {
  Eigen::VectorXd d;
  std::vector<ReissnerFrame> elems;
};

RollUp solveRollUp(int n, double l, double angle, double m, int steps) {
  const MaterialSet mat = reissnerMaterial();
  const Vec2 t(std::cos(angle), std::sin(angle));
  RollUp s;
  for (int e = 0; e < n; ++e)
    s.elems.emplace_back(mat, std::array<int, 2>{e, e + 1}, (l * e / n) * t, (l * (e + 1) / n) * t);
  const int ndof = 3 * (n + 1), nf = ndof - 3;
  s.d = Eigen::VectorXd::Zero(ndof);
  const StepRule rule = makeRule(Scheme::Static);
  for (int step = 1; step <= steps; ++step) {
    Eigen::VectorXd fext = Eigen::VectorXd::Zero(ndof);
    fext(ndof - 1) = m * step / steps;
    bool converged = false;
    for (int it = 0; it < 40 && !converged; ++it) {
      Eigen::MatrixXd k = Eigen::MatrixXd::Zero(ndof, ndof);
      Eigen::VectorXd r = -fext;
      for (int e = 0; e < n; ++e) {
        const ElemVec de = s.d.segment<6>(3 * e);
        ElemVec re;
        ElemMat ke;
        EXPECT_TRUE(s.elems[e].evaluate({de, de, de, de}, rule, true, re, ke).ok);
        r.segment<6>(3 * e) += re;
        k.block<6, 6>(3 * e, 3 * e) += ke;
      }
      const Eigen::VectorXd dd = k.bottomRightCorner(nf, nf).partialPivLu().solve(-r.tail(nf));
      s.d.tail(nf) += dd;
      converged = dd.norm() < 1e-13 * l;
    }
    EXPECT_TRUE(converged) << "step " << step;
  }
  return s;
}

// verification.md V1: nodal rotations k Phi/n are exact and each element
// chord is straight at the mean rotation, so the tip position is the sum of
// chords (l/n)(cos((k+1/2) dtheta), sin(...)): the exact arc times
// c_n = (dtheta/2)/sin(dtheta/2).
void checkRollUp(int n, double lambda, double angle) {
  const MaterialSet mat = reissnerMaterial();
  const double l = 2.0, ei = mat.EI(), m = lambda * 2 * kPi * ei / l, phi = 2 * kPi * lambda;
  const RollUp s = solveRollUp(n, l, angle, m, 16);
  const double dth = phi / n;
  Vec2 chordSum = Vec2::Zero();
  for (int k = 0; k < n; ++k)
    chordSum += l / n * Vec2(std::cos((k + 0.5) * dth), std::sin((k + 0.5) * dth));
  const Vec2 t(std::cos(angle), std::sin(angle));
  const Vec2 tipPosition = s.d.segment<2>(3 * n) + l * t;
  EXPECT_LT((tipPosition - test::rot(angle) * chordSum).norm(), 1e-9 * l);
  for (int k = 0; k <= n; ++k) EXPECT_NEAR(s.d(3 * k + 2), k * dth, 1e-9);
  if (std::abs(std::sin(0.5 * dth)) > 0.1) {
    const double cn = 0.5 * dth / std::sin(0.5 * dth);
    const Vec2 exact(l * std::sin(phi) / phi, l * (1 - std::cos(phi)) / phi);
    EXPECT_LT((tipPosition - cn * (test::rot(angle) * exact)).norm(), 1e-9 * l);
  }
  if (lambda == 1.0 && n >= 2) {
    EXPECT_LT(tipPosition.norm(), 1e-9 * l);  // closed circle
  }
  for (const ReissnerFrame& e : s.elems) {
    EXPECT_NEAR(e.sectionForces().M, m, 1e-9 * m);
    EXPECT_NEAR(e.sectionForces().N, 0.0, 1e-9 * m / l);
    EXPECT_NEAR(e.sectionForces().V, 0.0, 1e-9 * m / l);
  }
}

TEST(ReissnerFrameRollUp, OneElement) {
  checkRollUp(1, 0.5, 0.0);
  checkRollUp(1, 1.0, 0.0);
}

TEST(ReissnerFrameRollUp, SeveralElementsCloseTheCircle) {
  for (int n : {2, 4}) {
    checkRollUp(n, 0.5, 0.0);
    checkRollUp(n, 1.0, 0.0);
  }
  checkRollUp(4, 1.5, 0.0);  // beyond the full circle: rotation 3 pi at the tip
}

TEST(ReissnerFrameRollUp, InclinedCantileverGivesRotatedAnswer) {
  checkRollUp(2, 1.0, 0.6);
  checkRollUp(4, 0.75, -2.4);
}

}  // namespace
}  // namespace c2d
