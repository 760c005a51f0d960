// A joint at the face of a rigid end zone (elements/JointedElement.h with
// elements/RigidEnds.h): the wrapped element's face follows the master's arm,
// the face moment is the joint's, the condensed tangent is the derivative of
// the residual (central differences) under every step rule, the shift's rates
// follow the step rule, a restart file keeps them, and under the mid-point
// scheme a free member with rigid zones spinning about its joint conserves
// its energy.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <sstream>
#include <tuple>

#include "core/Model.h"
#include "elements/JointedElement.h"
#include "elements/Joints.h"
#include "elements/LinearFrame.h"
#include "elements/ReissnerFrame.h"
#include "solvers/Analysis.h"
#include "solvers/TimeIntegrator.h"
#include "tests/unit/JointTestSupport.h"

namespace c2d {
namespace {

enum class Inner { Reissner, Timoshenko };

// From (0.3, 0.1) to (1.5, 0.9) (1.44 m), rigid zones of 0.3 and 0.25 m.
const Vec2 kX1(0.3, 0.1), kX2(1.5, 0.9);
constexpr std::array<double, 2> kOffsets{0.3, 0.25};

std::unique_ptr<Element> makeInner(Inner kind) {
  const MaterialSet m =
      test::resultantMaterial(kind == Inner::Reissner ? Kinematics::Finite : Kinematics::Small);
  if (kind == Inner::Reissner)
    return std::make_unique<ReissnerFrame>(m, std::array{3, 4}, kX1, kX2, kOffsets);
  return std::make_unique<LinearFrame>(m, std::array{3, 4}, kX1, kX2, kOffsets);
}

Vec2 turned(double a, const Vec2& x) { return test::rot(a) * x; }

StepRule ruleFor(Scheme s) { return test::integratorRule(s); }

// A rigid turn from t_n, perturbed (0.15 rad and m for the Reissner element,
// else 0.05), random rates at t_n.
ElementKinematics trialKinematics(std::mt19937& gen, Inner kind, int trial) {
  return test::trialKinematics(gen, kX1, kX2, kind == Inner::Reissner ? 0.15 : 0.05, trial);
}

// The arm's motion (R(t) - I) a, or its linear part t W a.
Vec2 armMotion(Inner kind, const Vec2& a, double t) {
  return kind == Inner::Reissner ? Vec2(turned(t, a) - a) : Vec2(t * Vec2(-a.y(), a.x()));
}

using Case = std::tuple<Scheme, Inner, int>;
class RigidJointTangent : public ::testing::TestWithParam<Case> {};

TEST_P(RigidJointTangent, FaceFollowsTheMasterAndTangentMatchesCentralDifferences) {
  // Named copies, not a structured binding: the lambdas below capture them.
  const Scheme scheme = std::get<0>(GetParam());
  const Inner kind = std::get<1>(GetParam());
  const int slaveEnd = std::get<2>(GetParam());
  std::mt19937 gen(23 + 3 * static_cast<int>(kind) + slaveEnd);
  JointedElement e(makeInner(kind), slaveEnd, 7);
  ASSERT_TRUE(e.hasArm());
  const Vec2 a = e.arm();
  EXPECT_NEAR(a.norm(), kOffsets[slaveEnd], 1e-15);
  e.setRelativeState(0.3, 0.5, -0.2, Vec2(0.1, -0.2), Vec2(0.3, 0.4));
  const StepRule rule = ruleFor(scheme);
  const int t = 3 * slaveEnd, kr = t + 2;
  const auto next = [&](int trial) { return trialKinematics(gen, kind, trial); };
  ASSERT_NO_FATAL_FAILURE(test::checkAtTrials(
      e, rule, next,
      [&](int trial, const ElementKinematics& kin, const ElemVec& r, const ElemMat& k) {
        const double psiM = kin.d(kr), psiR = e.relativeRotation(), psiS = psiM + psiR;
        EXPECT_NEAR(e.slaveRotation(), psiS, 1e-15);
        // The wrapped element's face is where the master's arm puts it.
        const ElementKinematics in = e.innerKinematics(kin, psiR);
        EXPECT_NEAR(in.d(kr), psiS, 1e-15);
        const Vec2 face = in.d.segment<2>(t) + armMotion(kind, a, psiS);
        EXPECT_LT((face - kin.d.segment<2>(t) - armMotion(kind, a, psiM)).norm(), 1e-14);
        // Its force at the face: no moment there (the joint), the face force on
        // the master's translations, its moment about the node on the master's rotation.
        ElemVec rin;
        ElemMat kin6;
        ASSERT_TRUE(e.inner().evaluate(in, rule, true, rin, kin6).ok);
        const Vec2 f = rin.segment<2>(t);
        // The wrapped element's nodal moment: the face's plus the face force's
        // about its (shifted) node, by its own arm map (the exact or, under the
        // mid-point scheme, the algorithmic lever; the linear one for SMALl).
        auto lever = [&](double th, double thn) {
          if (kind != Inner::Reissner) return Vec2(-a.y(), a.x());
          if (scheme != Scheme::MidPoint) return Vec2(turned(th + 0.5 * M_PI, a));
          return Vec2(std::cos(0.5 * (th - thn)) * turned(0.5 * (th + thn) + 0.5 * M_PI, a));
        };
        const double faceMoment = rin(kr) - lever(psiS, in.dn(kr)).dot(f);
        EXPECT_LT(std::abs(faceMoment), 1e-10 * rin.cwiseAbs().maxCoeff()) << faceMoment;
        EXPECT_LT((r.segment<2>(t) - f).norm(), 1e-12 * f.norm());
        EXPECT_NEAR(r(kr), lever(psiM, kin.dn(kr)).dot(f), 1e-10 * rin.cwiseAbs().maxCoeff());
        EXPECT_LT((r.segment<3>(3 - t) - rin.segment<3>(3 - t)).norm(), 1e-12 * rin.norm());

        // The shift's rates follow the step rule.
        const Vec2 ds =
            e.shiftAt(psiM, psiR) - e.shiftAt(kin.dn(kr), e.committedRelativeRotation());
        EXPECT_LT((e.shiftVelocity() -
                   rule.velocity(ds, e.committedShiftVelocity(), e.committedShiftAcceleration()))
                      .norm(),
                  1e-12);
        EXPECT_LT((in.d.segment<2>(t) - kin.d.segment<2>(t) - e.shiftAt(psiM, psiR)).norm(), 1e-15);
        test::expectTangentMatchesDifferences(e, kin, rule, k, 2e-7,
                                              "scheme " + std::to_string(static_cast<int>(scheme)) +
                                                  ", trial " + std::to_string(trial));
      }));
}

INSTANTIATE_TEST_SUITE_P(RigidJoint, RigidJointTangent,
                         ::testing::Combine(::testing::Values(Scheme::Static, Scheme::Newmark,
                                                              Scheme::MidPoint),
                                            ::testing::Values(Inner::Reissner, Inner::Timoshenko),
                                            ::testing::Values(0, 1)));

// A joint with friction at a face: the tangent matches central differences.
TEST(RigidJoint, FrictionAtAFaceTangentMatchesCentralDifferences) {
  for (Scheme scheme : {Scheme::Static, Scheme::Newmark, Scheme::MidPoint})
    for (Inner kind : {Inner::Reissner, Inner::Timoshenko})
      for (int slaveEnd : {0, 1}) {
        std::mt19937 gen(11 + static_cast<int>(kind) + slaveEnd);
        JointedElement e(makeInner(kind), slaveEnd, 7);
        e.setRelativeState(0.3, 0.5, -0.2, Vec2(0.1, -0.2), Vec2(0.3, 0.4));
        const double Mr = 40;
        e.setFriction(Mr, 0.3);
        const StepRule rule = ruleFor(scheme);
        const auto next = [&](int trial) { return trialKinematics(gen, kind, trial); };
        ASSERT_NO_FATAL_FAILURE(test::checkAtTrials(
            e, rule, next,
            [&](int /*trial*/, const ElementKinematics& kin, const ElemVec& r, const ElemMat& k) {
              test::expectTangentMatchesDifferences(
                  e, kin, rule, k, 2e-6, "scheme " + std::to_string(static_cast<int>(scheme)));
            }));
      }
}

// A link (joints at both ends, both at faces) by the nested iteration: each
// wrapped element's face where its master's arm puts it, the tangent the
// derivative of the residual.
TEST(RigidJoint, LinkWithZonesAtBothFacesTangentMatchesCentralDifferences) {
  for (Scheme scheme : {Scheme::Static, Scheme::MidPoint})
    for (Inner kind : {Inner::Reissner, Inner::Timoshenko}) {
      std::mt19937 gen(31 + static_cast<int>(kind));
      auto inner = std::make_unique<JointedElement>(makeInner(kind), 0, 7);
      inner->setRelativeState(0.3, 0.5, -0.2);
      JointedElement link(std::move(inner), 1, 8);
      link.setRelativeState(-0.2, -0.4, 0.3);
      ASSERT_TRUE(link.hasArm());
      const StepRule rule = ruleFor(scheme);
      const auto next = [&](int trial) { return trialKinematics(gen, kind, trial); };
      ASSERT_NO_FATAL_FAILURE(test::checkAtTrials(
          link, rule, next,
          [&](int /*trial*/, const ElementKinematics& kin, const ElemVec& r, const ElemMat& k) {
            const auto& j = dynamic_cast<const JointedElement&>(link.inner());
            const ElementKinematics in = j.innerKinematics(
                link.innerKinematics(kin, link.relativeRotation()), j.relativeRotation());
            for (int end : {0, 1}) {
              const Vec2 a = end == 0 ? j.arm() : link.arm();
              const int t = 3 * end;
              const Vec2 face = in.d.segment<2>(t) + armMotion(kind, a, in.d(t + 2));
              EXPECT_LT((face - kin.d.segment<2>(t) - armMotion(kind, a, kin.d(t + 2))).norm(),
                        1e-14);
            }
            test::expectTangentMatchesDifferences(
                link, kin, rule, k, 2e-7, "scheme " + std::to_string(static_cast<int>(scheme)));
          }));
    }
}

// The shift's rates go through a restart file.
TEST(RigidJoint, RestartKeepsTheShiftRates) {
  JointedElement e(makeInner(Inner::Reissner), 0, 7);
  e.setRelativeState(0.3, 0.5, -0.2, Vec2(0.1, -0.2), Vec2(0.3, 0.4));
  std::stringstream io;
  e.writeState(io);
  JointedElement back(makeInner(Inner::Reissner), 0, 7);
  back.readState(io);
  EXPECT_EQ(back.committedShiftVelocity(), Vec2(0.1, -0.2));
  EXPECT_EQ(back.committedShiftAcceleration(), Vec2(0.3, 0.4));
  EXPECT_EQ(back.shiftVelocity(), Vec2(0.1, -0.2));
  EXPECT_EQ(back.committedRelativeRotation(), 0.3);
}

// Two free rods of two Reissner elements each (FINIte, EA 1e5, GA 5e4, EI 200,
// 1 kg/m, no gravity, no supports) joined by a free joint at node 2: rod 2's
// first element has a rigid zone of `zone` at the joint (its joint is at the
// face) and one at its other end. They fly apart spinning at 4 rad/s, vibrating,
// the joint folding at 3 rad/s relative. Under the mid-point scheme with
// alpha = 0 the energy is exact; with alpha > 0 it never grows.
double worstEnergyChange(double zone, double alpha, double& maxRelative) {
  Model m;
  MaterialSet mat = test::resultantMaterial(Kinematics::Finite);
  mat.resEA = 1e5;
  mat.resGA = 5e4;
  mat.resEI = 2e2;
  mat.density = 1.0;
  mat.A = 1.0;
  mat.I = 1e-3;
  m.materials()[1] = mat;
  for (const Vec2& x :
       {Vec2(0, 0), Vec2(0.5, 0.1), Vec2(1.0, 0.2), Vec2(1.0, 0.2), Vec2(1.4, 0.6), Vec2(1.8, 1.0)})
    m.addNode(x);
  const std::array<std::array<int, 2>, 4> elements{{{0, 1}, {1, 2}, {3, 4}, {4, 5}}};
  for (int e = 0; e < 4; ++e) {
    const auto n = elements[e];
    const std::array<double, 2> o = e == 2 ? std::array{zone, 0.1} : std::array{0.0, 0.0};
    m.setElement(e, std::make_unique<ReissnerFrame>(mat, n, m.coord(n[0]), m.coord(n[1]), o));
  }
  m.joints().push_back({2, 3, JointForm::Condensed});
  installJoints(m);
  const std::vector<JointedElement*> joints = jointedElements(m);
  EXPECT_EQ(joints.size(), 1u);
  if (joints.size() != 1) return 1e300;
  EXPECT_EQ(joints.front()->hasArm(), zone > 0);

  Analysis an(m);
  an.setIntegrator(TimeIntegrator::midPoint(alpha, 0));
  an.setDt(0.01);
  State& st = an.state();
  st.resize(m.numNodes());
  const double w = 4.0;
  for (int n = 0; n < m.numNodes(); ++n) {
    const Vec2 r = m.coord(n) - Vec2(1.0, 0.2);
    st.v.segment<2>(3 * n) = w * Vec2(-r.y(), r.x()) + 0.3 * Vec2(std::sin(n), std::cos(3.0 * n));
    st.v(3 * n + 2) = w;
  }
  st.vn = st.v;
  joints.front()->setRelativeState(0, 3.0, 0);
  const double e0 = an.energy().total();
  double worst = 0, previous = e0;
  maxRelative = 0;
  for (int s = 0; s < 300; ++s) {
    IterationInfo info;
    EXPECT_TRUE(an.advance()) << "step " << s;
    for (int i = 0; i < 40 && !info.converged; ++i) EXPECT_TRUE(an.iterate(false, false, info));
    EXPECT_TRUE(info.converged) << "step " << s;
    if (!info.converged) return 1e300;
    an.commit();
    const double e = an.energy().total();
    worst = std::max(worst, alpha == 0 ? std::abs(e - e0) : e - previous);
    previous = e;
    maxRelative = std::max(maxRelative, std::abs(joints.front()->relativeRotation()));
  }
  return worst / e0;
}

TEST(RigidJoint, FreeMemberConservesEnergyUnderTheMidPointScheme) {
  for (double alpha : {0.0, 0.1}) {
    double folded = 0;
    EXPECT_LT(worstEnergyChange(0.15, alpha, folded), 1e-10) << "alpha " << alpha;
    EXPECT_GT(folded, 0.5);  // the joint turns
  }
}

}  // namespace
}  // namespace c2d
