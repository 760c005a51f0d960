// JointedElement (the paper's condensed revolute joint, eqs 55, 66-68):
// tangents vs central finite differences of the condensed residual for every
// scheme and inner element, rigid-body and mechanism modes, commit/revert of
// the relative rotation, local failures, and the hinge's safeguarded local
// iteration on a kinked residual. The joint set-up is JointsTest's.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <memory>
#include <random>
#include <tuple>

#include "elements/JointedElement.h"
#include "elements/LinearFrame.h"
#include "elements/ReissnerFrame.h"
#include "tests/unit/ElementTestSupport.h"
#include "tests/unit/JointTestSupport.h"
#include "tests/unit/StubElementSupport.h"

namespace c2d {
namespace {

enum class Inner { Reissner, Timoshenko, EulerBernoulli };

MaterialSet frameMaterial(Inner kind) {
  return test::resultantMaterial(kind == Inner::Reissner ? Kinematics::Finite : Kinematics::Small,
                                 kind != Inner::EulerBernoulli);
}

std::unique_ptr<Element> makeInner(Inner kind, const Vec2& x1, const Vec2& x2) {
  const MaterialSet m = frameMaterial(kind);
  if (kind == Inner::Reissner) return std::make_unique<ReissnerFrame>(m, std::array{3, 4}, x1, x2);
  return std::make_unique<LinearFrame>(m, std::array{3, 4}, x1, x2);
}

StepRule ruleFor(Scheme s) { return test::integratorRule(s); }

// The tangent checks' element: kind's element from x1 to x2 jointed at its end
// slaveEnd (slave node 7), a relative rotation under way.
const Vec2 kTrialX1(0.3, 0.1), kTrialX2(1.5, 0.9);
std::unique_ptr<JointedElement> trialJoint(Inner kind, int slaveEnd) {
  auto e = std::make_unique<JointedElement>(makeInner(kind, kTrialX1, kTrialX2), slaveEnd, 7);
  e->setRelativeState(0.3, 0.5, -0.2);
  return e;
}

// Trial `trial` of the tangent checks on kind's element: a rigid turn of 0.8
// trial rad from t_n, perturbed (0.15 for the Reissner element, else 0.05),
// with random rates and accelerations at t_n.
ElementKinematics trialKinematics(std::mt19937& gen, Inner kind, int trial) {
  return test::trialKinematics(gen, kTrialX1, kTrialX2, kind == Inner::Reissner ? 0.15 : 0.05,
                               trial);
}

using TangentCase = std::tuple<Scheme, Inner, int>;
class JointedElementTangent : public ::testing::TestWithParam<TangentCase> {};

TEST_P(JointedElementTangent, CondensedTangentMatchesCentralDifferences) {
  // Named copies, not structured bindings: lambdas capture them (clang 14).
  const Scheme scheme = std::get<0>(GetParam());
  const Inner kind = std::get<1>(GetParam());
  const int slaveEnd = std::get<2>(GetParam());
  std::mt19937 gen(17 + 3 * static_cast<int>(kind) + slaveEnd);
  const std::unique_ptr<JointedElement> joint = trialJoint(kind, slaveEnd);
  JointedElement& e = *joint;
  EXPECT_EQ(e.slaveNode(), slaveEnd == 0 ? 3 : 4);
  EXPECT_EQ(e.nodes()[slaveEnd], 7);
  EXPECT_EQ(e.nodes()[1 - slaveEnd], slaveEnd == 0 ? 4 : 3);
  const StepRule rule = ruleFor(scheme);
  const auto next = [&](int trial) { return trialKinematics(gen, kind, trial); };
  ASSERT_NO_FATAL_FAILURE(test::checkAtTrials(
      e, rule, next,
      [&](int trial, const ElementKinematics& kin, const ElemVec& r, const ElemMat& k) {
        const int kr = 3 * slaveEnd + 2;
        // No moment on the master's rotation, and the local equation solved to round-off.
        EXPECT_LT(std::abs(r(kr)), 1e-12 * r.cwiseAbs().maxCoeff());
        EXPECT_LT(k.row(kr).cwiseAbs().maxCoeff(), 1e-12 * k.cwiseAbs().maxCoeff());
        ElemVec rin;
        ElemMat kin6;
        ASSERT_TRUE(
            e.inner()
                .evaluate(e.innerKinematics(kin, e.relativeRotation()), rule, true, rin, kin6)
                .ok);
        EXPECT_EQ((rin - r).cwiseAbs().maxCoeff(), 0.0);
        EXPECT_NEAR(e.slaveRotation(), kin.d(kr) + e.relativeRotation(), 1e-15);

        // Eq (68) from the wrapped element's tangent at the solution.
        const ElemMat cond = kin6 - kin6.col(kr) * kin6.row(kr) / kin6(kr, kr);
        EXPECT_LT((cond - k).cwiseAbs().maxCoeff(), 1e-13 * k.cwiseAbs().maxCoeff());

        test::expectTangentMatchesDifferences(e, kin, rule, k, 2e-7,
                                              "scheme " + std::to_string(static_cast<int>(scheme)) +
                                                  ", trial " + std::to_string(trial));
      }));
}

INSTANTIATE_TEST_SUITE_P(
    JointedElement, JointedElementTangent,
    ::testing::Combine(::testing::Values(Scheme::Static, Scheme::Newmark, Scheme::MidPoint),
                       ::testing::Values(Inner::Reissner, Inner::Timoshenko, Inner::EulerBernoulli),
                       ::testing::Values(0, 1)));

// A link, an element with joints at both ends (a member failed twice): both
// relative rotations are solved together (JointedElement::evaluateLink). No
// moment on either master, each wrapper's residual the innermost element's
// at the relative rotations found, the tangent the derivative of the
// residual, and the same solution as the nested iteration's (the inner joint
// with a friction moment too small to matter takes that path).
class JointedElementLink : public ::testing::TestWithParam<std::tuple<Scheme, Inner>> {};

// An element that counts its evaluations (the one inside a link).
class Counted final : public Element {
 public:
  Counted(std::unique_ptr<Element> e, int& count) : e_(std::move(e)), count_(count) {}
  std::array<int, 2> nodes() const override { return e_->nodes(); }
  void setNodes(const std::array<int, 2>& n) override { e_->setNodes(n); }
  int materialNumber() const override { return e_->materialNumber(); }
  std::string typeName() const override { return e_->typeName(); }
  Status evaluate(const ElementKinematics& kin, const StepRule& rule, bool wantTangent, ElemVec& r,
                  ElemMat& k) override {
    ++count_;
    return e_->evaluate(kin, rule, wantTangent, r, k);
  }
  ElemMat mass() const override { return e_->mass(); }
  ElemVec bodyLoad(const Vec2& g) const override { return e_->bodyLoad(g); }
  void commit() override { e_->commit(); }
  void revert() override { e_->revert(); }
  double strainEnergy() const override { return e_->strainEnergy(); }
  SectionForces sectionForces() const override { return e_->sectionForces(); }

 private:
  std::unique_ptr<Element> e_;
  int& count_;
};

TEST_P(JointedElementLink, BothJointsSolvedAtOnceAsByTheNestedIteration) {
  const auto [scheme, kind] = GetParam();
  std::mt19937 gen(29 + static_cast<int>(kind));
  int evaluations = 0, evaluationsNested = 0, linkCalls = 0;
  auto makeLink = [&, kind = kind](double innerFriction) {
    auto inner = std::make_unique<JointedElement>(
        std::make_unique<Counted>(makeInner(kind, kTrialX1, kTrialX2),
                                  innerFriction > 0 ? evaluationsNested : evaluations),
        0, 7);
    inner->setRelativeState(0.3, 0.5, -0.2);
    inner->setFriction(innerFriction, 1.0);
    auto link = std::make_unique<JointedElement>(std::move(inner), 1, 8);
    link->setRelativeState(-0.2, -0.4, 0.3);
    return link;
  };
  const std::unique_ptr<JointedElement> link = makeLink(0), nested = makeLink(1e-300);
  EXPECT_EQ(link->nodes(), (std::array<int, 2>{7, 8}));
  const StepRule rule = ruleFor(scheme);
  for (int trial = 0; trial < 3; ++trial) {
    const ElementKinematics kin = trialKinematics(gen, kind, trial);
    ElemVec r, rn;
    ElemMat k, kn;
    const int before = evaluations;
    ASSERT_TRUE(link->evaluate(kin, rule, true, r, k).ok);
    linkCalls += evaluations - before;
    ASSERT_TRUE(nested->evaluate(kin, rule, true, rn, kn).ok);
    const double scale = r.cwiseAbs().maxCoeff();
    EXPECT_LT(std::abs(r(2)), 1e-12 * scale);
    EXPECT_LT(std::abs(r(5)), 1e-12 * scale);
    auto& inner = static_cast<JointedElement&>(link->inner());
    auto& innerN = static_cast<JointedElement&>(nested->inner());
    EXPECT_NEAR(link->relativeRotation(), nested->relativeRotation(), 1e-12);
    EXPECT_NEAR(inner.relativeRotation(), innerN.relativeRotation(), 1e-12);
    EXPECT_NEAR(link->relativeVelocity(), nested->relativeVelocity(), 1e-9);
    EXPECT_NEAR(inner.relativeVelocity(), innerN.relativeVelocity(), 1e-9);
    EXPECT_NEAR(link->slaveRotation(), nested->slaveRotation(), 1e-12);
    EXPECT_NEAR(inner.slaveRotation(), innerN.slaveRotation(), 1e-12);
    EXPECT_LT((r - rn).cwiseAbs().maxCoeff(), 1e-10 * scale);
    EXPECT_LT((k - kn).cwiseAbs().maxCoeff(), 1e-9 * k.cwiseAbs().maxCoeff());
    // The innermost element's residual at the rotations found.
    ElemVec rin;
    ElemMat kin6;
    ASSERT_TRUE(
        inner.inner()
            .evaluate(inner.innerKinematics(link->innerKinematics(kin, link->relativeRotation()),
                                            inner.relativeRotation()),
                      rule, true, rin, kin6)
            .ok);
    EXPECT_EQ((rin - r).cwiseAbs().maxCoeff(), 0.0);
    const ElemMat fd = test::centralDifferenceTangent(*link, kin, rule);
    EXPECT_LT((fd - k).cwiseAbs().maxCoeff(), 2e-7 * k.cwiseAbs().maxCoeff())
        << "scheme " << static_cast<int>(scheme) << ", trial " << trial << "\nK =\n"
        << k << "\nFD =\n"
        << fd;
  }
  // Solved at once, in fewer evaluations of the innermost element; from the
  // first-order start of a nearby state (a Newton iteration's next), in two:
  // one step and the evaluation at the solution.
  EXPECT_LT(linkCalls, evaluationsNested)
      << linkCalls << " evaluations, nested " << evaluationsNested;
  ElementKinematics near = trialKinematics(gen, kind, 2);
  ElemVec r;
  ElemMat k;
  ASSERT_TRUE(link->evaluate(near, rule, true, r, k).ok);
  near.d += 1e-7 * test::randomVec(gen, 1.0);
  const int before = evaluations;
  ASSERT_TRUE(link->evaluate(near, rule, true, r, k).ok);
  EXPECT_EQ(evaluations - before, 2);
}

INSTANTIATE_TEST_SUITE_P(JointedElement, JointedElementLink,
                         ::testing::Combine(::testing::Values(Scheme::Static, Scheme::Newmark,
                                                              Scheme::MidPoint),
                                            ::testing::Values(Inner::Reissner, Inner::Timoshenko)));

// With friction Mr the moment on the master is the friction's reaction, at most
// Mr, and the condensed tangent is still the derivative of the residual, when
// the joint slides (w >> eps) and when it sticks (w ~ eps).
TEST(JointedElement, FrictionTangentMatchesCentralDifferences) {
  for (Scheme scheme : {Scheme::Static, Scheme::Newmark, Scheme::MidPoint})
    for (Inner kind : {Inner::Reissner, Inner::Timoshenko})
      for (double eps : {1e-3, 0.3}) {
        std::mt19937 gen(5 + static_cast<int>(kind));
        const std::unique_ptr<JointedElement> joint = trialJoint(kind, 1);
        JointedElement& e = *joint;
        const double Mr = 40;
        e.setFriction(Mr, eps);
        const StepRule rule = ruleFor(scheme);
        const auto next = [&](int trial) { return trialKinematics(gen, kind, trial); };
        ASSERT_NO_FATAL_FAILURE(test::checkAtTrials(
            e, rule, next,
            [&](int /*trial*/, const ElementKinematics& kin, const ElemVec& r, const ElemMat& k) {
              const int kr = 5;
              EXPECT_LE(std::abs(r(kr)), Mr);
              EXPECT_GT(std::abs(r(kr)), 1e-3 * Mr);
              test::expectTangentMatchesDifferences(e, kin, rule, k, 2e-6,
                                                    "scheme " +
                                                        std::to_string(static_cast<int>(scheme)) +
                                                        ", eps " + std::to_string(eps));
            }));
      }
}

TEST(JointedElement, FiniteRigidMotionReleasesThePinnedEnd) {
  // A stress-free element turned rigidly by a large angle: psi_r goes back to
  // zero from any start (the pin does not care about the slave's former angle),
  // and the residual vanishes.
  const Vec2 x1(0.0, 0.0), x2(2.0, 0.5);
  for (int end : {0, 1}) {
    JointedElement e(makeInner(Inner::Reissner, x1, x2), end, 0);
    e.setRelativeState(0.4);
    for (double w : {0.0, 1.3, 4.0, -9.0}) {
      const ElemVec d = test::rigidMotion(x1, x2, w, Vec2::Zero(), Vec2(1.0, -3.0));
      ElemVec r;
      ElemMat k;
      ASSERT_TRUE(
          e.evaluate({d, d, ElemVec::Zero(), ElemVec::Zero()}, ruleFor(Scheme::Static), true, r, k)
              .ok);
      EXPECT_LT(r.norm(), 1e-10) << "w = " << w;
      EXPECT_NEAR(e.relativeRotation(), 0.0, 1e-12);
      EXPECT_LT(e.strainEnergy(), 1e-22);
      // The master's own rotation does not matter: the slave rotation is w.
      ElemVec d2 = d;
      d2(3 * end + 2) += 2.5;
      ASSERT_TRUE(e.evaluate({d2, d2, ElemVec::Zero(), ElemVec::Zero()}, ruleFor(Scheme::Static),
                             true, r, k)
                      .ok);
      EXPECT_LT(r.norm(), 1e-10);
      EXPECT_NEAR(e.relativeRotation(), -2.5, 1e-12);
      EXPECT_NEAR(e.slaveRotation(), w, 1e-12);
    }
  }
}

TEST(JointedElement, NullSpaceHasRigidModesAndTheMasterRotation) {
  const Vec2 x1(0.2, -0.1), x2(1.1, 0.7);
  for (Inner kind : {Inner::Timoshenko, Inner::EulerBernoulli, Inner::Reissner}) {
    JointedElement e(makeInner(kind, x1, x2), 1, 9);
    ElemVec r;
    ElemMat k;
    const ElemVec zero = ElemVec::Zero();
    ASSERT_TRUE(e.evaluate({zero, zero, zero, zero}, ruleFor(Scheme::Static), true, r, k).ok);
    const Vec2 dx = x2 - x1;
    ElemVec tx, ty, rz, master;
    tx << 1, 0, 0, 1, 0, 0;
    ty << 0, 1, 0, 0, 1, 0;
    rz << 0, 0, 1, -dx.y(), dx.x(), 1;  // infinitesimal rotation about node 1
    master.setZero();
    master(5) = 1;
    const double kmax = k.cwiseAbs().maxCoeff();
    for (const ElemVec& mode : {tx, ty, rz, master}) EXPECT_LT((k * mode).norm(), 1e-12 * kmax);
    // Exactly four zero modes: the remaining stiffness is positive definite.
    Eigen::SelfAdjointEigenSolver<ElemMat> eig(0.5 * (k + k.transpose()));
    EXPECT_GT(eig.eigenvalues()(4), 1e-6 * kmax);
    EXPECT_LT(std::abs(eig.eigenvalues()(3)), 1e-10 * kmax);
  }
}

TEST(JointedElement, CommitRevertAndRelativeRatesFollowTheStepRule) {
  std::mt19937 gen(5);
  const Vec2 x1(0.0, 0.0), x2(1.0, 0.0);
  JointedElement e(makeInner(Inner::Reissner, x1, x2), 0, 2);
  e.setRelativeState(0.2, 0.7, -1.5);
  const StepRule rule = ruleFor(Scheme::Newmark);
  const ElementKinematics a{test::randomVec(gen, 0.1), test::randomVec(gen, 0.1),
                            test::randomVec(gen, 1.0), test::randomVec(gen, 1.0)};
  ElementKinematics b = a;
  b.d += test::randomVec(gen, 0.1);
  ElemVec r;
  ElemMat k;
  ASSERT_TRUE(e.evaluate(a, rule, true, r, k).ok);
  const double psiA = e.relativeRotation();
  EXPECT_NEAR(e.relativeVelocity(), rule.velocity(psiA - 0.2, 0.7, -1.5), 1e-14);
  EXPECT_NEAR(e.relativeAcceleration(), rule.acceleration(psiA - 0.2, 0.7, -1.5), 1e-12);
  EXPECT_EQ(e.committedRelativeRotation(), 0.2);
  const double velA = e.relativeVelocity(), accA = e.relativeAcceleration();
  e.commit();
  EXPECT_EQ(e.committedRelativeRotation(), psiA);
  EXPECT_EQ(e.committedRelativeVelocity(), velA);
  EXPECT_EQ(e.committedRelativeAcceleration(), accA);

  ASSERT_TRUE(e.evaluate(b, rule, true, r, k).ok);
  const double psiB = e.relativeRotation();
  const ElemVec rB = r;
  EXPECT_NE(psiB, psiA);
  e.revert();
  EXPECT_EQ(e.relativeRotation(), psiA);
  EXPECT_EQ(e.relativeVelocity(), velA);
  ASSERT_TRUE(e.evaluate(b, rule, true, r, k).ok);
  EXPECT_NEAR(e.relativeRotation(), psiB, 1e-14);
  EXPECT_LT((r - rB).cwiseAbs().maxCoeff(), 1e-10 * rB.cwiseAbs().maxCoeff());
}

TEST(JointedElement, KineticEnergyAndBodyLoadSeeTheSlave) {
  const Vec2 x1(0.0, 0.0), x2(1.0, 1.0);
  for (int end : {0, 1}) {
    JointedElement e(makeInner(Inner::EulerBernoulli, x1, x2), end, 5);
    e.setRelativeState(0.1, 2.0, 0.0);
    ElemVec v;
    v << 0.1, -0.2, 0.3, 0.4, 0.5, -0.6;
    ElemVec vin = v;
    vin(3 * end + 2) += 2.0;
    EXPECT_NEAR(e.kineticEnergy(v), 0.5 * vin.dot(e.mass() * vin), 1e-15);
    const Vec2 g(0.0, -9.81);
    const ElemVec fin = e.inner().bodyLoad(g), f = e.bodyLoad(g);
    EXPECT_NE(fin(3 * end + 2), 0.0);  // the Hermite element has end moments
    EXPECT_EQ(f(3 * end + 2), 0.0);
    EXPECT_EQ(f(3 * (1 - end) + 2), fin(3 * (1 - end) + 2));
    EXPECT_EQ(f.segment<2>(0), fin.segment<2>(0));
    EXPECT_EQ(e.typeName(), "frame-euler-bernoulli+joint");
  }
}

// Inner element of the failure tests: residual r = K d + (0 ... atan(d_k) ... 0).
class ScalarLawElement final : public test::StubElement {
 public:
  ScalarLawElement(double kkk, bool arctan)
      : StubElement("scalar-law"), kkk_(kkk), arctan_(arctan) {}
  Status evaluate(const ElementKinematics& kin, const StepRule&, bool, ElemVec& r,
                  ElemMat& k) override {
    r = ElemVec::Zero();
    k = ElemMat::Zero();
    r(2) = arctan_ ? std::atan(kin.d(2)) : kkk_ * kin.d(2);
    k(2, 2) = arctan_ ? 1.0 / (1.0 + kin.d(2) * kin.d(2)) : kkk_;
    return Status::success();
  }

 private:
  double kkk_;
  bool arctan_;
};

TEST(JointedElement, LocalFailuresAreReturnedAsStatus) {
  ElemVec r;
  ElemMat k;
  const ElemVec zero = ElemVec::Zero();
  // A negative relative-rotation stiffness condenses (a nonzero pivot); a zero one cannot.
  JointedElement negative(std::make_unique<ScalarLawElement>(-1.0, false), 0, 3);
  EXPECT_TRUE(negative.evaluate({zero, zero, zero, zero}, StepRule{}, true, r, k).ok);
  JointedElement singular(std::make_unique<ScalarLawElement>(0.0, false), 0, 3);
  Status st = singular.evaluate({zero, zero, zero, zero}, StepRule{}, true, r, k);
  EXPECT_FALSE(st.ok);
  EXPECT_NE(st.why.find("singular"), std::string::npos) << st.why;

  // Newton on atan diverges from 3 rad.
  JointedElement diverging(std::make_unique<ScalarLawElement>(0.0, true), 0, 3);
  ElemVec d = zero;
  d(2) = 3.0;
  st = diverging.evaluate({d, zero, zero, zero}, StepRule{}, true, r, k);
  EXPECT_FALSE(st.ok);
  // From 1 rad it converges, to psi_r = -1.
  d(2) = 1.0;
  JointedElement fine(std::make_unique<ScalarLawElement>(0.0, true), 0, 3);
  ASSERT_TRUE(fine.evaluate({d, zero, zero, zero}, StepRule{}, true, r, k).ok);
  EXPECT_NEAR(fine.relativeRotation(), -1.0, 1e-15);
}

// Inner element of the hinge's kinked residual: r_2 = 1 + f(d_2), f odd,
// stiff in a core |x| <= e (a joint that sticks) and ever softer beyond it
// (one that slips), f(x) = sign(x) |x|^p with p = 1/1.9: there Newton's step
// from x lands at -0.9 x, on the other side of the root and hardly nearer.
class KinkedLawElement final : public test::StubElement {
 public:
  static constexpr double kCore = 1e-6, kPower = 1 / 1.9;
  KinkedLawElement() : StubElement("kinked-law") {}
  Status evaluate(const ElementKinematics& kin, const StepRule&, bool, ElemVec& r,
                  ElemMat& k) override {
    double slope = 0;
    r = ElemVec::Zero();
    k = ElemMat::Zero();
    r(2) = 1 + law(kin.d(2), slope);
    k(2, 2) = slope;
    return Status::success();
  }
  static double law(double x, double& slope) {
    const double a = std::abs(x), coreSlope = std::pow(kCore, kPower - 1);
    if (a <= kCore) return slope = coreSlope, coreSlope * x;
    slope = kPower * std::pow(a, kPower - 1);
    return std::copysign(std::pow(a, kPower), x);
  }
};

// A hinge of Mu = 1 (softening over 1e6 rad: nearly constant) wrapping the
// kinked law, the master turned 1 rad: the stick moment 2 exceeds Mu and the
// hinge slips back to the root of G = 1 + f(1 + psi) - C(-psi) near psi = -1.
// Plain Newton bounces about the root and is still 0.9^60 of the way off after
// the iteration limit; the safeguarded iteration bisects the bracket instead.
TEST(JointedElement, HingeIterationBisectsWhereNewtonBouncesOnAKink) {
  double slope = 0;
  const double xiF = 1e6;
  auto G = [&](double psi, double& dG) {
    const double g = KinkedLawElement::law(1 + psi, slope) - psi / xiF;  // C = 1 + psi / xiF
    dG = slope - 1 / xiF;
    return g;
  };
  double psi = 0, dG = 0;
  int newton = 0;
  for (double g = G(psi, dG); newton < 60 && std::abs(g / dG) > 1e-9; g = G(psi, dG), ++newton)
    psi -= g / dG;
  EXPECT_EQ(newton, 60) << "plain Newton converged at psi = " << psi;
  EXPECT_GT(std::abs(1 + psi), 1e-4);  // still outside the core

  int count = 0;
  JointedElement hinge(std::make_unique<Counted>(std::make_unique<KinkedLawElement>(), count), 0,
                       3);
  hinge.setHinge(EndHinge(nullptr, -1, 1.0, xiF));
  const ElemVec zero = ElemVec::Zero();
  ElemVec d = zero, r;
  d(2) = 1.0;
  ElemMat k;
  const Status st = hinge.evaluate({d, zero, zero, zero}, StepRule{}, true, r, k);
  ASSERT_TRUE(st.ok) << st.why;
  EXPECT_LT(count, 30);  // the stick trial and fewer than 30 local iterations
  const double root = hinge.relativeRotation();
  EXPECT_LT(std::abs(1 + root), KinkedLawElement::kCore);
  EXPECT_NEAR(G(root, dG), 0.0, 1e-12);
  EXPECT_NEAR(hinge.hingeSlip(), -root, 1e-15);
}

}  // namespace
}  // namespace c2d
