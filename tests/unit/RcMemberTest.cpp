// RC members (SECTion): the elements' tangents with the axial law and the
// moment-axial interaction, against central differences of their residuals,
// small and finite kinematics, statics and the mid-point scheme, at large
// rotations; the hinge carried by a joint at a member's end.
#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <memory>
#include <string>

#include "core/StepRule.h"
#include "elements/InelasticFrame.h"
#include "elements/JointedElement.h"
#include "elements/ReissnerFrame.h"
#include "materials/AxialCapacity.h"
#include "materials/RcSection.h"
#include "materials/SectionLaws.h"
#include "tests/unit/ElementTestSupport.h"
#include "tests/unit/RcTestSupport.h"
#include "tests/unit/V2Material.h"

namespace c2d::test {
namespace {

// A beam section 0.3 x 0.5 m, C30, 3 bars of 20 mm at the bottom and 2 of
// 16 mm at the top (kN, m).
MaterialSet rcMaterial(Kinematics kin) {
  const double a20 = M_PI * 0.01 * 0.01, a16 = M_PI * 0.008 * 0.008;
  return rcSectionMaterial(kin, {{0.04, 2 * a16}, {0.45, 3 * a20}});
}

// The mid-point scheme (alpha = 0.1) and Newmark's, for steps of 0.01 s.
StepRule midPointRule(Scheme scheme = Scheme::MidPoint) {
  StepRule r;
  r.scheme = scheme;
  r.alpha = scheme == Scheme::MidPoint ? 0.1 : 0.0;
  r.ca = 4 / (1e-2 * 1e-2);
  r.av = -4 / 1e-2;
  r.aa = -1;
  return r;
}

double relativeError(const ElemMat& a, const ElemMat& b) {
  return (a - b).cwiseAbs().maxCoeff() / std::max(1.0, b.cwiseAbs().maxCoeff());
}

// Commits the element at d (static, from its committed state), then returns
// the kinematics of a trial state d + dd.
ElementKinematics committedAt(Element& e, const ElemVec& d, const ElemVec& dd) {
  ElementKinematics kin;
  kin.d = d;
  kin.dn = d;
  kin.vn.setZero();
  kin.an.setZero();
  ElemVec r;
  ElemMat k;
  EXPECT_TRUE(e.evaluate(kin, StepRule{}, true, r, k).ok);
  e.commit();
  kin.d = d + dd;
  return kin;
}

// At kin (past first yield: plastic, on the law of its N) the tangent of e
// under each rule matches central differences; `what` names the case.
template <class Frame>
void expectPlasticTangents(Frame& e, const ElementKinematics& kin,
                           std::initializer_list<StepRule> rules, const std::string& what) {
  for (const StepRule& rule : rules) {
    ElemVec r;
    ElemMat k;
    ASSERT_TRUE(e.evaluate(kin, rule, true, r, k).ok);
    EXPECT_GT(e.section().bulk.xi, 0);
    const ElemMat fd = centralDifferenceTangent(e, kin, rule, 1e-8);
    EXPECT_LT(relativeError(k, fd), 1e-5)
        << what << " scheme " << static_cast<int>(rule.scheme) << "\n"
        << k << "\n\n"
        << fd;
  }
}

TEST(RcMember, SmallElementTangentWithInteraction) {
  const MaterialSet mat = rcMaterial(Kinematics::Small);
  for (double stretch : {-2e-4, -4e-3, 0.0, 3e-5, 6e-5, 1e-3}) {
    InelasticFrame e(mat, {0, 1}, Vec2(0, 0), Vec2(1.2, 0.3));
    ElemVec d = ElemVec::Zero(), dd = ElemVec::Zero();
    // The bending of first yield at about the third step, the axial strain as given.
    d << 0, 0, -0.004, stretch * 1.2, 0.01, 0.006;
    dd << 0, 0, -0.0021, stretch * 0.1, 0.0005, 0.0023;
    const ElementKinematics kin = committedAt(e, d, dd);
    ASSERT_NO_FATAL_FAILURE(expectPlasticTangents(e, kin, {StepRule{}, midPointRule()},
                                                  "stretch " + std::to_string(stretch)));
  }
}

TEST(RcMember, FiniteElementTangentWithInteractionAtLargeRotations) {
  const MaterialSet mat = rcMaterial(Kinematics::Finite);
  for (double turn : {0.0, 1.1, -2.4}) {
    for (double stretch : {-3e-4, 0.0, 3e-5, 6e-5, 2e-3}) {
      ReissnerFrame e(mat, {0, 1}, Vec2(0, 0), Vec2(1.5, 0.0));
      // A rigid turn by `turn`, then a stretch and a curvature into the plastic range.
      const Vec2 p2(1.5 * (1 + stretch) * std::cos(turn), 1.5 * (1 + stretch) * std::sin(turn));
      ElemVec d;
      d << 0, 0, turn - 0.003, p2.x() - 1.5, p2.y(), turn + 0.004;
      ElemVec dd;
      dd << 0.0002, -0.0001, -0.0024, 0.0003, 0.0002, 0.0031;
      const ElementKinematics kin = committedAt(e, d, dd);
      ASSERT_NO_FATAL_FAILURE(expectPlasticTangents(
          e, kin, {StepRule{}, midPointRule(), midPointRule(Scheme::Newmark)},
          "turn " + std::to_string(turn) + " stretch " + std::to_string(stretch)));
    }
  }
}

// A member with its hinge at end 2 carried by a joint (elements/JointedElement
// with materials/EndHinge): sticking, slipping with the capacity following the
// member's axial force, and spent (a free joint). offsets: rigid end zones
// (the joint at the face of the one at end 2).
template <class Frame>
void expectHingeJointTangents(Kinematics kin, const StepRule& rule,
                              const std::array<double, 2>& offsets = {0.0, 0.0}) {
  const MaterialSet mat = rcMaterial(kin);
  for (double rot : {0.004, 0.02, 0.2}) {
    for (double stretch : {-2e-4, 0.0, 3e-5, 6e-5, 1e-4, 2e-3}) {
      auto inner =
          std::make_unique<Frame>(mat, std::array<int, 2>{0, 2}, Vec2(0, 0), Vec2(1.5, 0), offsets);
      JointedElement e(std::move(inner), 1, 1);
      const MomentLaw l = mat.capacity->at(1, 0.0);
      e.setHinge(EndHinge(mat.capacity, 1, l.Mu, l.xiF));
      ElemVec d, dd;
      d << 0, 0, 0.0, 1.5 * stretch, 0.0, 0.4 * rot;
      dd << 0.0001, 0.0, 0.0002, 1.5 * stretch * 0.1, 0.0002, rot;
      ElementKinematics k0 = committedAt(e, d, dd);
      k0.vn.setZero();
      ElemVec r;
      ElemMat k;
      ASSERT_TRUE(e.evaluate(k0, rule, true, r, k).ok);
      const HingeInfo h = e.hingeInfo();
      const ElemMat fd = centralDifferenceTangent(e, k0, rule, 1e-8);
      EXPECT_LT(relativeError(k, fd), 2e-5)
          << "rot " << rot << " stretch " << stretch << " slip " << h.softening << " failed "
          << h.failed << "\n" << k << "\n\n" << fd;
      if (rot == 0.02) {
        EXPECT_GT(e.hingeSlip(), e.committedHingeSlip());
      }
      if (rot == 0.2) {
        EXPECT_TRUE(h.failed);
      }
    }
  }
}

TEST(RcMember, HingeJointTangentSmall) {
  expectHingeJointTangents<InelasticFrame>(Kinematics::Small, StepRule{});
  expectHingeJointTangents<InelasticFrame>(Kinematics::Small, midPointRule());
}

TEST(RcMember, HingeJointTangentFinite) {
  for (const StepRule& rule : {StepRule{}, midPointRule(), midPointRule(Scheme::Newmark)})
    expectHingeJointTangents<ReissnerFrame>(Kinematics::Finite, rule);
}

TEST(RcMember, HingeJointAtTheFaceOfARigidZoneTangent) {
  for (const StepRule& rule : {StepRule{}, midPointRule()}) {
    expectHingeJointTangents<InelasticFrame>(Kinematics::Small, rule, {0.2, 0.4});
    expectHingeJointTangents<ReissnerFrame>(Kinematics::Finite, rule, {0.2, 0.4});
  }
  expectHingeJointTangents<ReissnerFrame>(Kinematics::Finite, midPointRule(Scheme::Newmark),
                                          {0.0, 0.4});
}

// A member at rest whose strain comes out of its node positions as +-1e-16
// (nodes not exactly on an axis: the ten-storey SECTion frame with its nodes
// moved by 1e-6 m, JITTer) starts Newton's method on the stiffer compression
// branch either way. With the tension branch's tangent (the bars alone, 13
// times softer here) its gravity step overshot and diverged (residual 457
// -> 1e30 kN in 29 iterations); unjittered it converged in 5. The force
// stays the branch's of the sign of the strain; beyond round-off (1e-14) the
// tangent is that branch's (a band of 1e-12 caught the catenary deck's free
// pieces at rest: Newton at a twelfth of the slope, 266 cuts instead of 17).
TEST(RcMember, AMemberAtRestTakesTheCompressionTangentWithinRoundOff) {
  const double EAc = 4.8e6, EAt = 3.77e5, Nt = 942, Ntu = 1017, Nc = 6371, eu = 0.05;
  const AxialCapacity ax(EAc, EAt, Nt, Ntu, Nc, eu);
  const AxialState rest;
  for (double eps : {1e-16, -1e-16, 0.0, 5e-15}) {
    const AxialResponse r = ax.returnMap(rest, eps);
    EXPECT_EQ(r.tangent, EAc) << "eps = " << eps;
    EXPECT_EQ(r.N, (eps > 0 ? EAt : EAc) * eps) << "eps = " << eps;
  }
  EXPECT_EQ(ax.returnMap(rest, 1e-13).tangent, EAt);
  EXPECT_EQ(ax.returnMap(rest, 1e-6).tangent, EAt);
  EXPECT_EQ(ax.returnMap(rest, -1e-6).tangent, EAc);
}

// The members' structural damping (DAMPing, materials/SectionDamping) with laws
// that follow the axial force: an RC section (a bounded axial force: the
// dashpot on the elastic axial strain) and hand-given laws with an interaction
// curve (INTEraction), each element type and dynamic scheme, from compression
// through the bars' yield, on the plastic branch of the law at its N.
StepRule dampedRule(Scheme scheme) {
  StepRule r = midPointRule(scheme);
  r.h = 1e-2;
  return r;
}

MaterialSet interactionMaterial(Kinematics kin) {
  MaterialSet m = v2::material(1, 1.25e6, kin);
  m.interaction = {{-3000, 300}, {-1000, 380}, {0, 274}, {800, 150}};
  deriveSectionLaws(m);
  return m;
}

// A member of mat from (0, 0) to (1.5, 0): the one-point Timoshenko element
// for small kinematics, the Reissner element for finite ones.
std::unique_ptr<Element> member(Kinematics kin, const MaterialSet& mat) {
  if (kin == Kinematics::Small)
    return std::make_unique<InelasticFrame>(mat, std::array<int, 2>{0, 1}, Vec2(0, 0),
                                            Vec2(1.5, 0));
  return std::make_unique<ReissnerFrame>(mat, std::array<int, 2>{0, 1}, Vec2(0, 0), Vec2(1.5, 0));
}

TEST(RcMember, DampedTangentsWithInteraction) {
  for (Kinematics kin : {Kinematics::Small, Kinematics::Finite}) {
    for (bool section : {true, false}) {
      MaterialSet mat = section ? rcMaterial(kin) : interactionMaterial(kin);
      mat.dampingA1 = 2e-3;  // f = a1/h = 0.2
      ASSERT_TRUE(mat.capacity);
      for (double stretch : {-4e-3, -2e-4, 0.0, 3e-5, 6e-5, 2e-3}) {
        const std::unique_ptr<Element> e = member(kin, mat);
        ElemVec d, dd;
        d << 0, 0, -0.003, 1.5 * stretch, 0.0, 0.004;
        dd << 0.0002, -0.0001, -0.0024, 1.5 * stretch * 0.1 + 0.0003, 0.0002, 0.0031;
        ElementKinematics k0 = committedAt(*e, d, dd);
        k0.vn.setConstant(0.1);
        for (Scheme scheme : {Scheme::MidPoint, Scheme::Newmark}) {
          const StepRule rule = dampedRule(scheme);
          ElemVec r, undamped;
          ElemMat k;
          ASSERT_TRUE(e->evaluate(k0, rule, true, r, k).ok);
          const ElemMat fd = centralDifferenceTangent(*e, k0, rule, 1e-8);
          EXPECT_LT(relativeError(k, fd), 1e-5)
              << "finite " << int(kin) << " section " << section << " stretch " << stretch
              << " scheme " << int(scheme) << "\n" << k << "\n\n" << fd;
          // The dashpot is there: the residual differs from the undamped one.
          MaterialSet plain = mat;
          plain.dampingA1 = 0;
          const std::unique_ptr<Element> u = member(kin, plain);
          ElementKinematics ku = committedAt(*u, d, dd);
          ku.vn.setConstant(0.1);
          ASSERT_TRUE(u->evaluate(ku, rule, false, undamped, k).ok);
          EXPECT_GT((r - undamped).norm(), 1e-3 * r.norm()) << "stretch " << stretch;
        }
      }
    }
  }
}

// A T-section member (SECTion TEE: the moments about the gross centroid, the
// flange on the top face) and an annular one: the finite element's tangent at
// large rotations against central differences, in the plastic range of
// either sign, compressed and stretched.
TEST(RcMember, FiniteElementTangentOfTheFlangedAndAnnularShapes) {
  for (SectionShapeKind shape : {SectionShapeKind::Tee, SectionShapeKind::Annulus}) {
    MaterialSet mat = rcMaterial(Kinematics::Finite);
    RcSectionData& d = *mat.section;
    d.shape = shape;
    if (shape == SectionShapeKind::Tee) {
      d.flangeWidth = 1.2;
      d.flangeDepth = 0.12;
    } else {
      d.b = d.h = 0.5;
      d.wall = 0.12;
    }
    deriveSectionLaws(mat);
    for (double curl : {1.0, -1.0})
      for (double stretch : {-3e-4, 0.0, 2e-3}) {
        ReissnerFrame e(mat, {0, 1}, Vec2(0, 0), Vec2(1.5, 0.0));
        const double turn = 0.9;
        const Vec2 p2(1.5 * (1 + stretch) * std::cos(turn), 1.5 * (1 + stretch) * std::sin(turn));
        ElemVec d0, dd;
        d0 << 0, 0, turn - 0.003 * curl, p2.x() - 1.5, p2.y(), turn + 0.004 * curl;
        dd << 0.0002, -0.0001, -0.0024 * curl, 0.0003, 0.0002, 0.0031 * curl;
        const ElementKinematics kin = committedAt(e, d0, dd);
        ASSERT_NO_FATAL_FAILURE(expectPlasticTangents(e, kin, {StepRule{}, midPointRule()},
                                                      std::to_string(static_cast<int>(shape)) +
                                                          " curl " + std::to_string(curl) +
                                                          " stretch " + std::to_string(stretch)));
      }
  }
}

}  // namespace
}  // namespace c2d::test
