// The geometrically exact beam with the hardening and softening laws
// (ReissnerFrame + materials/HingedBending): tangents against finite
// differences on every branch at large rotations, verification.md V2 at any
// rotation through a whole analysis (hinge event, failure into a joint, the
// dissipated energy), and the energy balance of dynamic runs in which hinges
// form, fail and rupture in flight and members hit the ground.
#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <numbers>
#include <sstream>
#include <utility>
#include <vector>

#include "core/Model.h"
#include "elements/JointedElement.h"
#include "elements/Joints.h"
#include "elements/ReissnerFrame.h"
#include "macro/DeckRunner.h"
#include "macro/deck/SolutionCommand.h"
#include "solvers/Analysis.h"
#include "solvers/ProportionalLoad.h"
#include "solvers/TimeIntegrator.h"
#include "tests/unit/DeckTestSupport.h"
#include "tests/unit/ElementTestSupport.h"
#include "tests/unit/RunDeckSupport.h"
#include "tests/unit/V2Material.h"

namespace c2d {
namespace {

using test::kinAt;
using test::tangentError;
using test::turned;

// verification.md V2.
using namespace test::v2;
constexpr double kL = 2.5;

MaterialSet v2Material() { return material(1, 1.25e6, Kinematics::Finite); }

class InelasticReissnerRotations : public ::testing::TestWithParam<double> {};

TEST_P(InelasticReissnerRotations, TangentMatchesFiniteDifferencesOnEveryBranch) {
  const double rho = GetParam(), phi = 0.7, l = 0.5;
  const Vec2 x1(1.0, -2.0), x2 = x1 + l * Vec2(std::cos(phi), std::sin(phi));
  const StepRule stat;
  StepRule mid;
  mid.scheme = Scheme::MidPoint;
  mid.alpha = 0.1;
  mid.ca = 4 / (1e-2 * 1e-2);
  mid.av = -4 / 1e-2;
  mid.aa = -1;
  StepRule newmark = mid;
  newmark.scheme = Scheme::Newmark;
  newmark.alpha = 0;

  // Elastic and both hardening branches from a virgin state, under every rule.
  for (double M : {20.0, 150.0, 271.0, -200.0}) {
    const double kappa = kappaOf(std::abs(M)) * (M > 0 ? 1 : -1);
    for (const StepRule& rule : {stat, mid, newmark}) {
      ReissnerFrame e(v2Material(), {0, 1}, x1, x2);
      const ElemVec dn = turned(l, phi, rho - 0.05, 1e-4, -1e-4, 0.5 * kappa);
      ElemVec r;
      ElemMat k;
      ASSERT_TRUE(e.evaluate(kinAt(dn, dn), stat, false, r, k));
      e.commit();
      const ElemVec d = turned(l, phi, rho, 2e-4, 1e-4, kappa);
      EXPECT_LT(tangentError(e, kinAt(d, dn), rule), 1e-6) << "M = " << M;
      EXPECT_NEAR(e.sectionForces().M, M, 1e-6 * kMu);
      EXPECT_FALSE(e.hinge().active);
    }
  }

  // The hinge: opened at Mu, on the softening branch, then fully softened.
  ReissnerFrame e(v2Material(), {0, 1}, x1, x2);
  const double kU = kappaOf(kMu);
  const ElemVec dU = turned(l, phi, rho, 0, 0, kU);
  ElemVec r;
  ElemMat k;
  ASSERT_TRUE(e.evaluate(kinAt(dU, dU), stat, true, r, k));
  EXPECT_NEAR(e.hingeDemand(), 1.0, 1e-9);
  e.commit();
  e.activateHinge();
  const double kpU = kU - kMu / kEI;
  const double kSoft = kU + 0.004;
  for (const StepRule& rule : {stat, mid}) {
    const ElemVec d = turned(l, phi, rho + 0.01, 1e-4, -1e-4, kSoft);
    EXPECT_LT(tangentError(e, kinAt(d, dU), rule), 1e-6);
    const HingeInfo h = e.hinge();
    EXPECT_TRUE(h.active);
    EXPECT_FALSE(h.failed);
    // t = Mu + Ks alpha equals the bulk moment EI (kappa - alpha/l - kp_u), at any rotation.
    EXPECT_NEAR(h.moment, kMu + kKs * h.jump, 1e-8);
    EXPECT_NEAR(h.moment, kEI * (kSoft - h.jump / l - kpU), 1e-8);
  }
  const double kFail = kU + 0.1;
  const ElemVec dF = turned(l, phi, rho, 1e-4, -1e-4, kFail);
  EXPECT_LT(tangentError(e, kinAt(dF, dU), stat), 1e-6);
  EXPECT_TRUE(e.hinge().failed);
  EXPECT_EQ(e.hinge().moment, 0.0);
  EXPECT_NEAR(e.hinge().jump, l * (kFail - kpU), 1e-12);
}

INSTANTIATE_TEST_SUITE_P(InelasticReissner, InelasticReissnerRotations,
                         ::testing::Values(0.0, 1.0, -2.5, 7.0));

// Cantilever of n FINIte elements with the V2 laws, clamped at node 0.
Model v2Cantilever(int n) {
  Model m;
  m.materials()[1] = v2Material();
  m.resizeNodes(n + 1);
  for (int i = 0; i <= n; ++i) m.setCoord(i, Vec2(kL * i / n, 0));
  for (int i = 0; i < n; ++i)
    m.setElement(i, std::make_unique<ReissnerFrame>(m.materials().at(1), std::array{i, i + 1},
                                                    m.coord(i), m.coord(i + 1)));
  m.bound(0) = {1, 1, 1};
  m.bound(n) = {0, 0, 1};
  return m;
}

// TANG,LINE,1 until converged (the line search carries Newton's method over
// the kinks of the hardening law).
bool converge(Analysis& an, int maxIterations = 30) {
  IterationInfo info;
  for (int i = 0; i < maxIterations; ++i) {
    const Status st = an.iterate(true, true, info);
    if (!st) {
      ADD_FAILURE() << st.why;
      return false;
    }
    if (info.converged) return true;
  }
  for (const IterationInfo& h : an.stepHistory())
    std::printf("  iteration %d: residual %.3e energy %.3e\n", h.iteration, h.residual, h.energy);
  return false;
}

TEST(InelasticReissnerV2, EndMomentThroughFailureToOneRadian) {
  const int n = 5;
  Model m = v2Cantilever(n);
  Analysis an(m);
  int events = 0;
  an.topologyEvents().onEvent = [&](const TopologyEvent& ev) {
    ++events;
    EXPECT_EQ(ev.kind, TopologyEvent::Kind::JointFormed);
    EXPECT_EQ(ev.element, 0);
  };
  const double kpU = kappaOf(kMu) - kMu / kEI;
  const double thetaU = kL * kappaOf(kMu), thetaF = kL * kpU + kMu / -kKs;
  EXPECT_NEAR(thetaU, 0.0835350, 5e-8);
  // The tip rotation is time (a ramp table), so that a located event is a time.
  an.setLoadFunction(1, ProportionalLoad::ramp());
  m.disp(n)[2] = 1.0;
  double peak = 0, worstBalance = 0;
  auto clampMoment = [&] {
    Eigen::VectorXd r;
    EXPECT_TRUE(an.reactions(r));
    return -r[2];
  };
  // Steps that land on the kinks of the law (Mc, My), so that the trapezoidal
  // work of the steps is the exact integral; the event at Mu is located.
  const double thetaC = kL * kMc / kEI, thetaY = kL * kappaOf(kMy);
  std::vector<double> thetas = {thetaC, thetaY};
  for (int i = 1; i <= 40; ++i) thetas.push_back(thetaF * i / 40);
  for (int i = 1; i <= 200; ++i) thetas.push_back(thetaF + (1.0 - thetaF) * i / 200);
  std::sort(thetas.begin(), thetas.end());
  double t = 0;
  for (double theta : thetas) {
    an.setDt(theta - t);
    t = theta;
    ASSERT_TRUE(an.advance());
    ASSERT_TRUE(converge(an)) << "theta = " << theta;
    ASSERT_TRUE(an.commit());
    const double M = clampMoment();
    if (theta < thetaU) {
      EXPECT_NEAR(kL * kappaOf(M), theta, 1e-9) << "theta = " << theta;
    } else if (theta <= thetaF) {
      EXPECT_NEAR(M, (theta - kL * kpU + kMu / kKs) / (kL / kEI + 1 / kKs), 1e-6)
          << "theta = " << theta;
    } else {
      EXPECT_NEAR(M, 0, 1e-6) << "theta = " << theta;
    }
    const Energy en = an.energy();
    peak = std::max({peak, en.external, en.dissipated});
    worstBalance = std::max(worstBalance, std::abs(en.balance()));
  }
  EXPECT_EQ(events, 1);  // the failed hinge became a joint, once
  EXPECT_NEAR(an.state().u[3 * n + 2], 1.0, 1e-12);
  const Energy en = an.energy();
  const double dissipated =
      kL * ((kMy * kMy - kMc * kMc) / (2 * kKh1) + (kMu * kMu - kMy * kMy) / (2 * kKh2)) +
      kMu * kMu / (2 * -kKs);
  EXPECT_NEAR(en.dissipated, dissipated, 1e-7 * dissipated);
  EXPECT_NEAR(en.strain, 0, 1e-9 * dissipated);
  EXPECT_LT(worstBalance, 1e-8 * peak);
}

// The two-story frame with FINIte elements and hinge laws pushed to 1.5 m
// (decks/finite/two_story_frame_finite.inp): six hinges fail into joints
// during the static push, each releasing the end moment its one-point element
// carried at the joint's end (shear times half the length; the hinge's moment
// is zero at the midpoint). That energy is what the joint's fracture takes:
// the balance, measured at every commit, closes to round-off (it was off by
// 1.6e-4 kN m, 6e-7 of the largest energy, the sum of the three jumps).
TEST(InelasticReissnerPush, TwoStoryFrameClosesItsBalanceThroughTheJointsItForms) {
  const testing::DeckTempDir scratch;
  const DeckOutcome o =
      testing::runSourceDeck(scratch, "finite/two_story_frame_finite.inp").outcome;
  ASSERT_EQ(o.exitCode, 0) << o.message;
  EXPECT_EQ(o.total.jointsFormed, 6);
  EXPECT_LT(o.total.energyError, 1e-8);
}

// A rod of four FINIte elements with hinge laws, pinned at its top end and
// released horizontally under gravity: hinges open in flight (located events),
// fail into joints and rupture; the mid-point scheme with alpha = 0 and 0.1.
struct FlyingRod {
  Model m;
  explicit FlyingRod(double thetaR) {
    m.materials()[1] = test::hingedRodMaterial(thetaR);
    m.gravity() = Vec2(0, -9.81);
    const int n = 4;
    m.resizeNodes(n + 1);
    for (int i = 0; i <= n; ++i) m.setCoord(i, Vec2(1.0 * i / n, 0));
    for (int i = 0; i < n; ++i)
      m.setElement(i, std::make_unique<ReissnerFrame>(m.materials().at(1), std::array{i, i + 1},
                                                      m.coord(i), m.coord(i + 1)));
    m.bound(0) = {1, 1, 0};
  }
  // A condensed joint at interior node n: element n (nodes n, n + 1) moves to
  // a slave of n. Returns the slave (installJoints makes the wrappers).
  int jointAt(int n) {
    const int slave = m.addNode(m.coord(n));
    m.element(n).setNodes({slave, n + 1});
    m.joints().push_back(Joint{n, slave, JointForm::Condensed});
    return slave;
  }
};

class InelasticReissnerFlight : public ::testing::TestWithParam<double> {};

TEST_P(InelasticReissnerFlight, HingesFormFailAndRuptureInFlightWithTheBalanceClosed) {
  const double alpha = GetParam();
  FlyingRod rod(1.0);
  Model& m = rod.m;
  Analysis an(m);
  an.setIntegrator(TimeIntegrator::midPoint(alpha, alpha));
  an.setDt(0.005);
  int opened = 0, formed = 0, ruptured = 0;
  double worstRatio = 0;
  an.onHingeActivated = [&](int, const HingeInfo& h) {
    ++opened;
    EXPECT_NEAR(std::abs(h.moment), 2.4, 2.4e-9);  // located at Mu
  };
  an.topologyEvents().onEvent = [&](const TopologyEvent& ev) {
    (ev.kind == TopologyEvent::Kind::JointFormed ? formed : ruptured)++;
  };
  // Every commit, those of located events included: no member above Mu, and a
  // commit of length zero (the one that opens a hinge) moves no joint.
  std::vector<std::pair<int, double>> psiBefore;
  double tBefore = -1;
  int versionBefore = -1, zeroLength = 0;
  // Energy is never created: the dissipation booked at every commit (hinge
  // events included, which commit inside a step) is never negative.
  // The balance at every commit too: the in-place ones of hinge openings book
  // what the opened element's evaluation changed.
  double dissipatedN = 0, created = 0, everyCommit = 0, balanceFirst = 0;
  bool first = true;
  an.onCommit = [&] {
    const Energy now = an.energy();
    const double d = now.dissipated;
    created = std::max(created, dissipatedN - d);
    dissipatedN = d;
    if (first) balanceFirst = now.balance();
    first = false;
    everyCommit = std::max(everyCommit, std::abs(now.balance() - balanceFirst));
    for (const auto& [e, h] : an.hingeCarriers())
      worstRatio = std::max(worstRatio, std::abs(h->hinge().moment) / 2.4);
    std::vector<std::pair<int, double>> psi;
    for (int e = 0; e < m.numElements(); ++e)
      if (auto* je = dynamic_cast<const JointedElement*>(&m.element(e)))
        psi.emplace_back(e, je->relativeRotation());
    if (an.state().t == tBefore && m.topologyVersion() == versionBefore) {
      ++zeroLength;
      EXPECT_EQ(psi, psiBefore) << "t = " << tBefore;
    }
    psiBefore = psi;
    tBefore = an.state().t;
    versionBefore = m.topologyVersion();
  };
  double peak = 0, worst = 0, balance0 = 0;
  // 2 s take the rod through two joints and a rupture.
  const int steps = 400;
  for (int s = 0; s < steps; ++s) {
    ASSERT_TRUE(an.advance());
    ASSERT_TRUE(converge(an, 40)) << "step " << s;
    ASSERT_TRUE(an.commit());
    for (const auto& [e, h] : an.hingeCarriers())
      worstRatio = std::max(worstRatio, std::abs(h->hinge().moment) / 2.4);
    const Energy en = an.energy();
    if (s == 0) balance0 = en.balance();
    peak = std::max({peak, en.kinetic, std::abs(en.external), en.dissipated});
    worst = std::max(worst, std::abs(en.balance() - balance0));
  }
  EXPECT_LT(created, 1e-8 * peak);
  EXPECT_GT(opened, 0);
  EXPECT_GT(formed, 0);
  EXPECT_GT(zeroLength, 0);
  EXPECT_LT(worstRatio, 1 + 1e-6);  // no member above its capacity
  EXPECT_LT(worst, 1e-8 * peak);
  EXPECT_LT(everyCommit, 1e-8 * peak);
  EXPECT_GT(an.energy().dissipated, 0);
  EXPECT_GT(ruptured, 0);
}

INSTANTIATE_TEST_SUITE_P(InelasticReissner, InelasticReissnerFlight, ::testing::Values(0.0, 0.1));

// The rod pinned 0.3 m above a penalty ground swings down and strikes it: the
// impact bends it past Mu; the balance closes with contact and its dissipation,
// and no node ends deeper in the ground than the penalty penetration of the
// rod's weight.
TEST(InelasticReissnerImpact, RodStrikesTheGroundWithTheBalanceClosed) {
  FlyingRod rod(10.0);
  Model& m = rod.m;
  for (int i = 0; i < m.numNodes(); ++i) m.setCoord(i, m.coord(i) + Vec2(0, 0.3));
  m.ground() = Ground{0.0, 1e5, 0.1};
  Analysis an(m);
  an.setIntegrator(TimeIntegrator::midPoint(0.05, 0.05));
  an.setDt(0.005);
  int opened = 0;
  an.onHingeActivated = [&](int, const HingeInfo&) { ++opened; };
  double peak = 0, worst = 0, balance0 = 0, maxContact = 0;
  for (int s = 0; s < 600; ++s) {
    ASSERT_TRUE(an.advance());
    ASSERT_TRUE(converge(an, 40)) << "step " << s;
    ASSERT_TRUE(an.commit());
    const Energy en = an.energy();
    if (s == 0) balance0 = en.balance();
    peak = std::max({peak, en.kinetic, std::abs(en.external), en.dissipated});
    worst = std::max(worst, std::abs(en.balance() - balance0));
    maxContact = std::max(maxContact, en.contact);
  }
  EXPECT_GT(maxContact, 0);  // it struck the ground
  EXPECT_GT(opened, 0);
  EXPECT_LT(worst, 1e-8 * peak);
  // The slave nodes of the joints formed in the run at their masters' places
  // (the state holds their positions at the moment the joints formed).
  syncSlaveNodes(m, an.state());
  double lowest = 1e300;
  for (int i = 0; i < m.numNodes(); ++i)
    lowest = std::min(lowest, m.coord(i).y() + an.state().u[3 * i + 1]);
  EXPECT_GT(lowest, -10 * 9.81 / 1e5);  // the whole weight on one node: W/k
}

// A joint past its rupture rotation whose node presses on the ground waits
// until the node leaves it: separating there would give the new node a penalty
// force of its own at the master's penetration (k p^2 / 2 out of nothing).
TEST(InelasticReissnerRupture, AJointOnTheGroundRupturesWhenItsNodeLeavesIt) {
  FlyingRod rod(0.1);
  Model& m = rod.m;
  m.bound(0) = {0, 0, 0};
  m.ground() = Ground{0.0, 1e5, 0.1};
  // Element 2 (nodes 2-3) on a slave of node 2.
  const int slave = rod.jointAt(2);
  ASSERT_EQ(installJoints(m), 1);
  jointedElements(m).front()->setRelativeState(0.3);
  State s;
  s.resize(m.numNodes());
  for (int i = 0; i < m.numNodes(); ++i) s.u[3 * i + 1] = -1e-3;  // 1 mm into the ground
  s.un = s.u;
  EXPECT_TRUE(ruptureJoints(m, s).empty());
  EXPECT_EQ(m.joints().size(), 1u);
  for (int i = 0; i < m.numNodes(); ++i) s.u[3 * i + 1] = 1e-3;  // lifted off
  s.un = s.u;
  const auto ruptured = ruptureJoints(m, s);
  ASSERT_EQ(ruptured.size(), 1u);
  EXPECT_EQ(ruptured[0].slave, slave);
  EXPECT_NEAR(ruptured[0].rotation, 0.3, 1e-15);
  EXPECT_TRUE(m.joints().empty());
  EXPECT_EQ(m.element(2).nodes()[0], slave);
}

// Next to a free end the moment grows as V x from zero, so no member breaks
// within the shortest piece Lb ~ Mu/Vu of one (SOFTening's Lb, a SECTion's
// from its STIRrups): a joint there turns on instead of rupturing, and the free
// ends a rupture leaves count at once. A 1 m rod held at both ends, joints at
// x = 0.25, 0.5, 0.75 m all past thetaR.
std::vector<RupturedJoint> ruptureJointsOfHeldRod(double lb,
                                                  std::vector<HeldJoint>* held = nullptr) {
  FlyingRod rod(0.1);
  Model& m = rod.m;
  m.materials().at(1).softening->pieceLength = lb;
  m.bound(0) = m.bound(4) = {1, 1, 1};
  for (int i = 1; i <= 3; ++i) rod.jointAt(i);
  EXPECT_EQ(installJoints(m), 3);
  for (JointedElement* j : jointedElements(m)) j->setRelativeState(0.3);
  State s;
  s.resize(m.numNodes());
  return ruptureJoints(m, s, held);
}

TEST(InelasticReissnerRupture, NoRuptureWithinTheShortestPieceOfAFreeEnd) {
  EXPECT_EQ(ruptureJointsOfHeldRod(0).size(), 3u);    // pieces of one element
  EXPECT_EQ(ruptureJointsOfHeldRod(0.2).size(), 3u);  // the joints 0.25 m apart
  // Lb = 0.3 m: the joint at x = 0.25 m ruptures first; the one at 0.5 m lies
  // within Lb of the free ends it left and turns on; the one at 0.75 m does not.
  std::vector<HeldJoint> kept;
  const std::vector<RupturedJoint> held = ruptureJointsOfHeldRod(0.3, &kept);
  ASSERT_EQ(held.size(), 2u);
  EXPECT_EQ(held[0].master, 1);
  EXPECT_EQ(held[1].master, 3);
  // The one that stays names the free end that holds it for the log: node
  // 1, the left piece's end at x = 0.25 m (the right piece's, its slave node,
  // lies there too).
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(kept[0].master, 2);
  EXPECT_EQ(kept[0].freeEnd, 1);
  EXPECT_EQ(kept[0].pieceLength, 0.3);
  EXPECT_NEAR(kept[0].rotation, 0.3, 1e-15);
  // A pinned end is free too: with node 0 free to turn the joint at 0.25 m
  // lies within Lb of it.
  FlyingRod rod(0.1);
  Model& m = rod.m;
  m.materials().at(1).softening->pieceLength = 0.3;
  rod.jointAt(1);
  ASSERT_EQ(installJoints(m), 1);
  jointedElements(m).front()->setRelativeState(0.3);
  State s;
  s.resize(m.numNodes());
  EXPECT_TRUE(ruptureJoints(m, s).empty());
  m.materials().at(1).softening->pieceLength = 0.2;
  EXPECT_EQ(ruptureJoints(m, s).size(), 1u);
}

}  // namespace
}  // namespace c2d
