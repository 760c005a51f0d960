// Failure-phase frame element: tangents by central differences, history
// round trips, and the V2 cantilever of verification.md solved with a small
// Newton loop that activates one hinge at a time.
#include "tests/unit/V2Material.h"
#include "elements/InelasticFrame.h"
#include "tests/unit/ElementTestSupport.h"

#include "elements/LinearFrame.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <memory>
#include <numbers>
#include <tuple>
#include <utility>
#include <vector>

namespace c2d {
namespace {

using test::staticKinematics;
using test::tangentError;

using namespace test::v2;
constexpr double kL = 2.5;

MaterialSet v2Material() { return material(3, 1.2e6); }

// Global displacements of an element of axis angle phi whose local dofs are dl.
ElemVec toGlobal(const ElemVec& dl, double phi) {
  const double c = std::cos(phi), s = std::sin(phi);
  ElemVec d;
  for (int n = 0; n < 2; ++n) {
    const int o = 3 * n;
    d(o) = c * dl(o) - s * dl(o + 1);
    d(o + 1) = s * dl(o) + c * dl(o + 1);
    d(o + 2) = dl(o + 2);
  }
  return d;
}

// Local dofs giving axial strain eps, shear strain gamma and kappa_d = (theta2 - theta1)/l.
ElemVec localState(double l, double eps, double gamma, double kappaD) {
  ElemVec dl;
  const double th1 = 0.01, th2 = th1 + kappaD * l;
  dl << 0, 0, th1, eps * l, (gamma + 0.5 * (th1 + th2)) * l, th2;
  return dl;
}

class InelasticFrameAngles : public ::testing::TestWithParam<double> {};

TEST_P(InelasticFrameAngles, TangentMatchesFiniteDifferencesOnEveryBranch) {
  const double phi = GetParam();
  const double l = 0.5;
  const Vec2 x1(1.0, -2.0), x2 = x1 + l * Vec2(std::cos(phi), std::sin(phi));
  const StepRule stat;

  // Elastic and the two hardening branches from a virgin state.
  for (double M : {20.0, 150.0, 271.0, -200.0}) {
    InelasticFrame e(v2Material(), {0, 1}, x1, x2);
    const ElementKinematics kin = staticKinematics(
        toGlobal(localState(l, 1e-4, 2e-4, kappaOf(std::abs(M)) * (M > 0 ? 1 : -1)), phi));
    EXPECT_LT(tangentError(e, kin, stat), 1e-6) << "M = " << M;
    EXPECT_NEAR(e.sectionForces().M, M, 1e-6 * kMu);
    EXPECT_FALSE(e.hinge().active);
  }

  // Active hinge on the softening branch, then fully softened.
  InelasticFrame e(v2Material(), {0, 1}, x1, x2);
  const double kU = kappaOf(kMu);
  ElemVec r;
  ElemMat k;
  ASSERT_TRUE(
      e.evaluate(staticKinematics(toGlobal(localState(l, 0, 0, kU), phi)), stat, true, r, k));
  e.commit();
  e.activateHinge();
  const double kpU = kU - kMu / kEI;
  // Bulk moment with alpha = 0 would be EI*(kappaD - kpU); a jump lowers it.
  const double kSoft = kU + 0.004;
  const ElementKinematics soft = staticKinematics(toGlobal(localState(l, 1e-4, -1e-4, kSoft), phi));
  EXPECT_LT(tangentError(e, soft, stat), 1e-6);
  const HingeInfo hs = e.hinge();
  EXPECT_TRUE(hs.active);
  EXPECT_FALSE(hs.failed);
  // Hinge equation: t = Mu + Ks*alpha equals the bulk moment EI*(kappaD - alpha/l - kpU).
  EXPECT_NEAR(hs.moment, kMu + kKs * hs.jump, 1e-8);
  EXPECT_NEAR(hs.moment, kEI * (kSoft - hs.jump / l - kpU), 1e-8);
  EXPECT_NEAR(e.sectionForces().M, hs.moment, 1e-12);
  EXPECT_DOUBLE_EQ(hs.position, 0.5);

  const double kFail = kU + 0.1;
  const ElementKinematics failed =
      staticKinematics(toGlobal(localState(l, 1e-4, -1e-4, kFail), phi));
  EXPECT_LT(tangentError(e, failed, stat), 1e-6);
  const HingeInfo hf = e.hinge();
  EXPECT_TRUE(hf.failed);
  EXPECT_EQ(hf.moment, 0.0);
  EXPECT_NEAR(hf.jump, l * (kFail - kpU), 1e-12);

  // Dynamic rule: residual carries M a_eff and the tangent ca*M.
  StepRule nm;
  nm.scheme = Scheme::Newmark;
  nm.ca = 4 / (1e-3 * 1e-3);
  nm.av = -4 / 1e-3;
  nm.aa = -1;
  MaterialSet heavy = v2Material();
  heavy.density = 2.5;
  heavy.A = 0.12;
  heavy.I = 1.6e-3;
  InelasticFrame d(heavy, {0, 1}, x1, x2);
  ElementKinematics kin = staticKinematics(toGlobal(localState(l, 1e-4, 2e-4, kappaOf(150)), phi));
  kin.vn.setConstant(0.3);
  kin.an.setConstant(-2.0);
  EXPECT_LT(tangentError(d, kin, nm), 1e-6);
}

INSTANTIATE_TEST_SUITE_P(InelasticFrame, InelasticFrameAngles,
                         ::testing::Values(0.0, std::numbers::pi / 6, 2.0, -std::numbers::pi / 2));

TEST(InelasticFrame, ElasticRangeAgreesWithLinearFrameUnderEveryScheme) {
  MaterialSet m = v2Material();
  m.density = 2.5;
  m.A = 0.12;
  m.I = 1.6e-3;
  const Vec2 x1(0.2, 0.4), x2(0.9, -0.1);
  StepRule stat, nm, mid;
  nm.scheme = Scheme::Newmark;
  nm.ca = 4e6;
  nm.av = -4e3;
  nm.aa = -1;
  mid.scheme = Scheme::MidPoint;
  mid.alpha = 0.1;
  mid.ca = 2e3;
  mid.av = -2e3;
  ElementKinematics kin;
  kin.d << 1e-4, -2e-4, 3e-4, -1e-4, 2e-4, 1e-4;
  kin.dn << 5e-5, -1e-4, 1e-4, 0, 1e-4, 2e-4;
  kin.vn.setConstant(0.01);
  kin.an.setConstant(-0.02);
  for (const StepRule& rule : {stat, nm, mid}) {
    for (MassType t : {MassType::Consistent, MassType::Lumped}) {
      m.mass = t;
      InelasticFrame e(m, {0, 1}, x1, x2);
      LinearFrame f(m, {0, 1}, x1, x2);
      ElemVec re, rf;
      ElemMat ke, kf;
      // The committed history belongs to d_n (the mid-point scheme takes M_n from it).
      ASSERT_TRUE(e.evaluate(staticKinematics(kin.dn), stat, false, re, ke));
      e.commit();
      ASSERT_TRUE(e.evaluate(kin, rule, true, re, ke));
      ASSERT_TRUE(f.evaluate(kin, rule, true, rf, kf));
      EXPECT_LT(std::abs(e.sectionForces().M), kMc);  // elastic range
      EXPECT_LT((re - rf).norm(), 1e-10 * rf.norm());
      EXPECT_LT((ke - kf).norm(), 1e-10 * kf.norm());
      EXPECT_LT((e.mass() - f.mass()).norm(), 1e-14);
      EXPECT_NEAR(e.strainEnergy(), f.strainEnergy(), 1e-10 * f.strainEnergy());
      EXPECT_LT(tangentError(e, kin, rule), 1e-6);
    }
  }
}

TEST(InelasticFrame, RigidBodyMotionIsStressFree) {
  const Vec2 x1(0.3, 0.1), x2(1.1, 0.7);
  InelasticFrame e(v2Material(), {0, 1}, x1, x2);
  const double th = 1e-3;
  ElemVec d;
  const Vec2 t(0.02, -0.01);
  for (int n = 0; n < 2; ++n) {
    const Vec2& x = n == 0 ? x1 : x2;
    d.segment<3>(3 * n) << t.x() - th * x.y(), t.y() + th * x.x(), th;
  }
  ElemVec r;
  ElemMat k;
  ASSERT_TRUE(e.evaluate(staticKinematics(d), StepRule{}, true, r, k));
  EXPECT_LT(r.norm(), 1e-9);
  EXPECT_LT((k * d).norm(), 1e-9 * k.norm());
  EXPECT_LT((k - k.transpose()).norm(), 1e-12 * k.norm());
}

TEST(InelasticFrame, CommitRevertRoundTripsAreExact) {
  const double l = 0.5;
  InelasticFrame e(v2Material(), {0, 1}, Vec2(0, 0), Vec2(0.3, 0.4));
  const double phi = std::atan2(0.4, 0.3);
  const StepRule stat;
  auto at = [&](double kd) {
    return staticKinematics(toGlobal(localState(l, 2e-4, 1e-4, kd), phi));
  };
  ElemVec r1, r2, r3, rb;
  ElemMat k1, k2, k3, kb;
  ASSERT_TRUE(e.evaluate(at(kappaOf(200)), stat, true, r1, k1));
  ASSERT_TRUE(e.evaluate(at(kappaOf(272)), stat, true, r2, k2));
  ASSERT_TRUE(e.evaluate(at(-kappaOf(100)), stat, true, r3, k3));
  e.revert();
  ASSERT_TRUE(e.evaluate(at(kappaOf(200)), stat, true, rb, kb));
  EXPECT_EQ(r1, rb);
  EXPECT_EQ(k1, kb);

  // Commit a hardened state, activate, soften in trial, then revert: the activation is dropped.
  ASSERT_TRUE(e.evaluate(at(kappaOf(kMu)), stat, true, r1, k1));
  e.commit();
  ASSERT_TRUE(e.evaluate(at(kappaOf(kMu) + 0.003), stat, true, r2, k2));
  const double hardened = e.sectionForces().M;
  EXPECT_GT(hardened, kMu);  // the element does not activate its hinge by itself
  EXPECT_GT(e.hingeDemand(), 1.0);
  EXPECT_FALSE(e.hinge().active);
  e.activateHinge();
  EXPECT_EQ(e.hingeDemand(), 0.0);
  ASSERT_TRUE(e.evaluate(at(kappaOf(kMu) + 0.003), stat, true, r3, k3));
  EXPECT_LT(e.sectionForces().M, kMu);
  EXPECT_GT(e.hinge().jump, 0.0);
  e.revert();
  EXPECT_FALSE(e.hinge().active);
  ASSERT_TRUE(e.evaluate(at(kappaOf(kMu) + 0.003), stat, true, rb, kb));
  EXPECT_EQ(rb, r2);
  EXPECT_EQ(kb, k2);
  EXPECT_EQ(e.sectionForces().M, hardened);

  // Activate and commit: the hinge stays; repeated evaluations are identical.
  e.activateHinge();
  ASSERT_TRUE(e.evaluate(at(kappaOf(kMu) + 0.003), stat, true, r3, k3));
  e.commit();
  ASSERT_TRUE(e.evaluate(at(kappaOf(kMu) + 0.006), stat, true, r1, k1));
  ASSERT_TRUE(e.evaluate(at(kappaOf(kMu) + 0.001), stat, true, r2, k2));
  ASSERT_TRUE(e.evaluate(at(kappaOf(kMu) + 0.006), stat, true, rb, kb));
  EXPECT_EQ(r1, rb);
  EXPECT_EQ(k1, kb);
  EXPECT_TRUE(e.hinge().active);
}

TEST(InelasticFrame, HingeUnloadsRigidlyAndTheBulkElastically) {
  const double l = 0.25;
  InelasticFrame e(v2Material(), {0, 1}, Vec2(0, 0), Vec2(l, 0));
  const StepRule stat;
  ElemVec r;
  ElemMat k;
  const double kU = kappaOf(kMu), kpU = kU - kMu / kEI;
  ASSERT_TRUE(e.evaluate(staticKinematics(localState(l, 0, 0, kU)), stat, true, r, k));
  e.commit();
  e.activateHinge();
  ASSERT_TRUE(e.evaluate(staticKinematics(localState(l, 0, 0, kU + 0.01)), stat, true, r, k));
  e.commit();
  const HingeInfo h = e.hinge();
  const double cap = kMu + kKs * h.softening;
  EXPECT_NEAR(h.moment, cap, 1e-8);
  // Unload: the jump stays, the bulk follows EI with the frozen plastic curvature.
  const double kd = kU + 0.01 - 0.0005;
  ASSERT_TRUE(e.evaluate(staticKinematics(localState(l, 0, 0, kd)), stat, true, r, k));
  EXPECT_EQ(e.hinge().jump, h.jump);
  EXPECT_NEAR(e.sectionForces().M, kEI * (kd - h.jump / l - kpU), 1e-8);
  EXPECT_NEAR(k(5, 5), kEI / l + 1.2e6 * l / 4, 1e-6 * kEI / l);  // elastic bulk bending + shear
  EXPECT_LT(e.sectionForces().M, cap);
  // Reverse loading reaches the reduced capacity in the other direction.
  const double kr = h.jump / l + kpU - (cap + 10) / kEI;
  ASSERT_TRUE(e.evaluate(staticKinematics(localState(l, 0, 0, kr)), stat, true, r, k));
  EXPECT_LT(e.hinge().jump, h.jump);
  EXPECT_NEAR(e.sectionForces().M, -(kMu + kKs * e.hinge().softening), 1e-8);
}

TEST(InelasticFrame, FrozenPlasticCurvatureIsTheOneAtMu) {
  // Activation from a committed state below Mu (either sign): the bulk freezes at
  // the plastic curvature where its yield radius reaches Mu, not at the committed one.
  const double l = 0.5, kpU = kappaOf(kMu) - kMu / kEI;
  for (double sign : {1.0, -1.0}) {
    InelasticFrame e(v2Material(), {0, 1}, Vec2(0, 0), Vec2(l, 0));
    ElemVec r;
    ElemMat k;
    ASSERT_TRUE(e.evaluate(staticKinematics(localState(l, 0, 0, sign * kappaOf(270))), StepRule{},
                           true, r, k));
    e.commit();
    const double kd = sign * (kappaOf(kMu) + 0.002);
    ASSERT_TRUE(e.evaluate(staticKinematics(localState(l, 0, 0, kd)), StepRule{}, true, r, k));
    e.activateHinge();
    ASSERT_TRUE(e.evaluate(staticKinematics(localState(l, 0, 0, kd)), StepRule{}, true, r, k));
    const HingeInfo h = e.hinge();
    EXPECT_NEAR(h.jump, sign * 0.002 * kEI / (kEI / l + kKs), 1e-12);
    EXPECT_NEAR(h.moment, sign * (kMu + kKs * h.softening), 1e-8);
    EXPECT_NEAR(h.moment, kEI * (kd - h.jump / l - sign * kpU), 1e-8);
  }
}

TEST(InelasticFrame, TooLongElementWithSofteningFailsWithAMessage) {
  // EI/|Ks| = 4.3139 m: an element of 5 m cannot carry the hinge.
  InelasticFrame e(v2Material(), {0, 1}, Vec2(0, 0), Vec2(0, 5.0));
  ElemVec r;
  ElemMat k;
  const StepRule stat;
  const ElementKinematics kin =
      staticKinematics(toGlobal(localState(5.0, 0, 0, kappaOf(kMu)), std::numbers::pi / 2));
  ASSERT_TRUE(e.evaluate(kin, stat, true, r, k));
  e.activateHinge();
  const Status st = e.evaluate(kin, stat, true, r, k);
  EXPECT_FALSE(st);
  EXPECT_NE(st.why.find("l_e = 5"), std::string::npos) << st.why;
  EXPECT_NE(st.why.find("EI/|Ks| = 4.31"), std::string::npos) << st.why;
}

TEST(InelasticFrame, HingeDemandNeedsSoftening) {
  MaterialSet m = v2Material();
  m.softening.reset();
  InelasticFrame e(m, {0, 1}, Vec2(0, 0), Vec2(1, 0));
  ElemVec r;
  ElemMat k;
  ASSERT_TRUE(
      e.evaluate(staticKinematics(localState(1, 0, 0, kappaOf(300))), StepRule{}, true, r, k));
  EXPECT_NEAR(e.sectionForces().M, 300, 1e-8);
  EXPECT_EQ(e.hingeDemand(), 0.0);
  e.activateHinge();
  EXPECT_FALSE(e.hinge().active);

  // Softening without hardening: elastic bulk, demand |M|/Mu.
  MaterialSet s = v2Material();
  s.hardening.reset();
  InelasticFrame f(s, {0, 1}, Vec2(0, 0), Vec2(1, 0));
  ASSERT_TRUE(f.evaluate(staticKinematics(localState(1, 0, 0, 137 / kEI)), StepRule{}, true, r, k));
  EXPECT_NEAR(f.sectionForces().M, 137, 1e-9);
  EXPECT_NEAR(f.hingeDemand(), 0.5, 1e-12);
}

TEST(InelasticFrame, MassBodyLoadAndEnergy) {
  MaterialSet m = v2Material();
  m.density = 2.5;
  m.A = 0.12;
  m.I = 1.6e-3;
  const Vec2 x1(0, 0), x2(1.2, 1.6);  // l = 2
  for (MassType t : {MassType::Consistent, MassType::Lumped}) {
    m.mass = t;
    InelasticFrame e(m, {0, 1}, x1, x2);
    const ElemMat M = e.mass();
    ElemVec ux = ElemVec::Zero(), rot = ElemVec::Zero();
    ux(0) = ux(3) = 1;
    rot(2) = rot(5) = 1;
    EXPECT_NEAR(ux.dot(M * ux), 2.5 * 0.12 * 2, 1e-12);   // total mass rhoA*l
    EXPECT_NEAR(rot.dot(M * rot), 2.5 * 1.6e-3 * 2, 1e-12);  // rotary inertia rhoI*l
    EXPECT_LT((M - M.transpose()).norm(), 1e-15);
  }
  InelasticFrame e(m, {0, 1}, x1, x2);
  const ElemVec f = e.bodyLoad(Vec2(0, -9.81));
  EXPECT_NEAR(f(1), -0.5 * 2.5 * 0.12 * 2 * 9.81, 1e-12);
  EXPECT_NEAR(f(4), f(1), 1e-15);
  EXPECT_EQ(f(0), 0.0);
  EXPECT_EQ(f(2), 0.0);
  EXPECT_EQ(f(5), 0.0);

  // Elastic energy: pure bending M = 30 below Mc on l = 2 gives M^2 l/(2 EI).
  ElemVec r;
  ElemMat k;
  const double phi = std::atan2(1.6, 1.2);
  ASSERT_TRUE(e.evaluate(staticKinematics(toGlobal(localState(2, 0, 0, 30 / kEI), phi)), StepRule{},
                         true, r, k));
  EXPECT_NEAR(e.strainEnergy(), 30 * 30 * 2 / (2 * kEI), 1e-12);
  // Axial + shear parts.
  ASSERT_TRUE(e.evaluate(staticKinematics(toGlobal(localState(2, 1e-4, 2e-4, 0), phi)), StepRule{},
                         true, r, k));
  EXPECT_NEAR(e.strainEnergy(), 0.5 * 2 * (3.6e6 * 1e-8 + 1.2e6 * 4e-8), 1e-12);
  const SectionForces s = e.sectionForces();
  EXPECT_NEAR(s.N, 3.6e6 * 1e-4, 1e-8);
  EXPECT_NEAR(s.V, 1.2e6 * 2e-4, 1e-8);
}

// Cantilever along x, clamped at node 0, tip rotation prescribed; static Newton
// from a tangent predictor, one hinge activation at a time (largest demand above 1).
// A step that takes a demand past 1 is cut back to where it equals 1 (secant on the
// demand, piecewise linear in theta), the hinge is activated there and committed,
// then the step is completed.
class Cantilever {
 public:
  explicit Cantilever(int n)
      : n_(n), d_(Eigen::VectorXd::Zero(3 * (n + 1))), dc_(d_) {
    for (int i = 0; i < n; ++i)
      elems_.push_back(std::make_unique<InelasticFrame>(
          v2Material(), std::array<int, 2>{i, i + 1}, Vec2(kL * i / n, 0), Vec2(kL * (i + 1) / n, 0)));
  }

  // Goes to tip rotation theta and commits; returns the tip moment.
  double step(double theta) {
    double M = solve(theta);
    auto [best, most] = largestDemand();
    if (most <= 1 + 1e-9) return commit(), M;
    double lo = dc_(tip()), demLo = committedDemand_, hi = theta, demHi = most;
    for (int it = 0; it < 20 && std::abs(most - 1) > 1e-13; ++it) {
      const double mid = lo + (hi - lo) * (1 - demLo) / (demHi - demLo);
      solve(mid);
      std::tie(best, most) = largestDemand();
      (most > 1 ? hi : lo) = mid;
      (most > 1 ? demHi : demLo) = most;
    }
    EXPECT_NEAR(most, 1, 1e-12);
    elems_[best]->activateHinge();
    activationTheta_ = d_(tip());
    solve(d_(tip()));  // the activated state is already in equilibrium
    commit();
    M = solve(theta);
    EXPECT_LE(largestDemand().second, 1 + 1e-9);  // no second hinge
    commit();
    return M;
  }

  int activeHinges() const {
    int a = 0;
    for (const auto& e : elems_) a += e->hinge().active;
    return a;
  }
  HingeInfo activeHinge() const {
    for (const auto& e : elems_)
      if (e->hinge().active) return e->hinge();
    return {};
  }
  double tipDeflection() const { return d_(3 * n_ + 1); }
  double activationTheta() const { return activationTheta_; }

 private:
  int tip() const { return 3 * n_ + 2; }
  int nf() const { return 3 * n_ - 1; }  // free dofs 3 .. tip-1

  double solve(double theta) {
    Eigen::VectorXd res;
    Eigen::MatrixXd K;
    d_ = dc_;
    // Tangent predictor: the prescribed increment enters through the tangent at the
    // committed state.
    assemble(res, K);
    const Eigen::VectorXd rhs = -(res.segment(3, nf()) + K.block(3, tip(), nf(), 1) * (theta - d_(tip())));
    d_.segment(3, nf()) += K.block(3, 3, nf(), nf()).partialPivLu().solve(rhs);
    d_(tip()) = theta;
    for (int it = 0; it < 10; ++it) {
      assemble(res, K);
      const Eigen::VectorXd rf = res.segment(3, nf());
      if (rf.norm() < 1e-9) return res(tip());
      d_.segment(3, nf()) += K.block(3, 3, nf(), nf()).partialPivLu().solve(-rf);
    }
    ADD_FAILURE() << "no convergence at theta = " << theta;
    return res(tip());
  }

  std::pair<int, double> largestDemand() const {
    int best = -1;
    double most = 0;
    for (int i = 0; i < n_; ++i)
      if (elems_[i]->hingeDemand() > most) most = elems_[i]->hingeDemand(), best = i;
    return {best, most};
  }

  void commit() {
    for (auto& e : elems_) e->commit();
    dc_ = d_;
    committedDemand_ = largestDemand().second;
  }

  void assemble(Eigen::VectorXd& r, Eigen::MatrixXd& K) {
    const int ndof = 3 * (n_ + 1);
    r = Eigen::VectorXd::Zero(ndof);
    K = Eigen::MatrixXd::Zero(ndof, ndof);
    for (int i = 0; i < n_; ++i) {
      const ElemVec de = d_.segment<6>(3 * i);
      ElemVec re;
      ElemMat ke;
      const Status st = elems_[i]->evaluate(staticKinematics(de), StepRule{}, true, re, ke);
      EXPECT_TRUE(st) << st.why;
      r.segment<6>(3 * i) += re;
      K.block<6, 6>(3 * i, 3 * i) += ke;
    }
  }

  int n_;
  Eigen::VectorXd d_, dc_;  // trial and committed displacements
  double committedDemand_ = 0, activationTheta_ = 0;
  std::vector<std::unique_ptr<InelasticFrame>> elems_;
};

class InelasticFrameV2 : public ::testing::TestWithParam<int> {};

TEST_P(InelasticFrameV2, CantileverUnderEndRotationReproducesV2) {
  const int n = GetParam();
  Cantilever c(n);
  const double thetaU = kL * kappaOf(kMu);
  EXPECT_NEAR(thetaU, 0.0835350, 5e-8);
  const double kpU = kappaOf(kMu) - kMu / kEI;  // plastic curvature at Mu
  const double thetaF = kL * kpU + kMu / -kKs;   // complete failure (M = 0)

  // Equal steps up to complete failure; one of them crosses Mu and is cut there.
  const int steps = 20;
  for (int i = 1; i <= steps; ++i) {
    const double theta = thetaF * i / steps;
    const double M = c.step(theta);
    if (theta < thetaU) {
      // Pre-peak: uniform moment, mesh independent.
      EXPECT_NEAR(kL * kappaOf(M), theta, 1e-10) << "step " << i;
      EXPECT_NEAR(c.tipDeflection(), kL * theta / 2, 1e-10);
      EXPECT_EQ(c.activeHinges(), 0);
    } else {
      // Post-peak: theta = L(kpU + M/EI) + (M - Mu)/Ks with exactly one hinge.
      const double expected = (theta - kL * kpU + kMu / kKs) / (kL / kEI + 1 / kKs);
      EXPECT_NEAR(M, expected, 1e-7) << "step " << i;
      ASSERT_EQ(c.activeHinges(), 1);
      const HingeInfo h = c.activeHinge();
      EXPECT_NEAR(h.moment, M, 1e-7);
      EXPECT_NEAR(h.jump, (M - kMu) / kKs, 1e-10);
      EXPECT_NEAR(h.softening, h.jump, 1e-15);
    }
  }
  // The hinge opened at theta_tip = 0.0835350 (the V2 value at Mu).
  EXPECT_NEAR(c.activationTheta(), thetaU, 1e-11);
  EXPECT_NEAR(c.activeHinge().moment, 0, 1e-6);
  EXPECT_NEAR(c.activeHinge().jump, kMu / -kKs, 1e-9);

  // Beyond complete failure: a free hinge takes the whole extra rotation.
  const double M = c.step(thetaF + 0.01);
  EXPECT_NEAR(M, 0, 1e-7);
  EXPECT_TRUE(c.activeHinge().failed);
  EXPECT_NEAR(c.activeHinge().jump, kMu / -kKs + 0.01, 1e-9);
  EXPECT_EQ(c.activeHinges(), 1);
}

INSTANTIATE_TEST_SUITE_P(InelasticFrame, InelasticFrameV2, ::testing::Values(1, 5, 10));

}  // namespace
}  // namespace c2d
