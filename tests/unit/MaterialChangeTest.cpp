// Material data changed during an analysis (core/MaterialChange.h,
// elements/MaterialUpdate.h): every frame element keeps its section forces at
// the committed state and its history, takes the new stiffness for the
// increments from there, and refuses the changes its history cannot follow.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <sstream>

#include "tests/unit/V2Material.h"
#include "core/Hinge.h"
#include "core/Model.h"
#include "core/State.h"
#include "elements/InelasticFrame.h"
#include "elements/JointedElement.h"
#include "elements/LinearFrame.h"
#include "elements/MaterialUpdate.h"
#include "elements/ReissnerFrame.h"
#include "tests/unit/ElementTestSupport.h"

namespace c2d {
namespace {

using test::staticKinematics;

// Evaluates e at d (static rule), commits, returns the residual.
ElemVec evaluateAndCommit(Element& e, const ElemVec& d) {
  ElemVec r;
  ElemMat k;
  EXPECT_TRUE(e.evaluate(staticKinematics(d), StepRule{}, false, r, k).ok);
  e.commit();
  return r;
}

ElemVec residual(Element& e, const ElemVec& d, ElemMat* tangent = nullptr) {
  ElemVec r;
  ElemMat k;
  EXPECT_TRUE(e.evaluate(staticKinematics(d), StepRule{}, tangent != nullptr, r, k).ok);
  if (tangent) *tangent = k;
  return r;
}

void expectForcesNear(const SectionForces& a, const SectionForces& b, double tol) {
  EXPECT_NEAR(a.N, b.N, tol);
  EXPECT_NEAR(a.V, b.V, tol);
  EXPECT_NEAR(a.M, b.M, tol);
}

const Vec2 kX1(1.0, 2.0), kX2(1.0 + 0.6 * std::cos(0.7), 2.0 + 0.6 * std::sin(0.7));

class LinearFrameChange : public ::testing::TestWithParam<std::tuple<bool, bool>> {};

TEST_P(LinearFrameChange, ForcesKeptAndIncrementsTakeTheNewStiffness) {
  const auto [shearBefore, shearAfter] = GetParam();
  const MaterialSet before = test::resultantMaterial(Kinematics::Small, shearBefore);
  MaterialSet after = test::resultantMaterial(Kinematics::Small, shearAfter);
  *after.resEI *= 2;
  *after.resEA *= 3;
  *after.resGA *= 0.5;
  after.density = 1.5;
  after.mass = MassType::Lumped;

  std::mt19937 gen(7);
  LinearFrame e(before, {0, 1}, kX1, kX2);
  const ElemVec d1 = test::randomVec(gen, 1e-3);
  const ElemVec r1 = evaluateAndCommit(e, d1);
  const SectionForces f1 = e.sectionForces();

  ASSERT_TRUE(e.setMaterial(after, d1).ok);
  // The end forces and section forces at the committed state are the old ones.
  const ElemVec r1Again = residual(e, d1);
  EXPECT_LT((r1Again - r1).norm(), 1e-10 * r1.norm());
  expectForcesNear(e.sectionForces(), f1, 1e-9 * (std::abs(f1.N) + std::abs(f1.M) + 1));

  // An increment is resisted by the new stiffness.
  const LinearFrame fresh(after, {0, 1}, kX1, kX2);
  const ElemVec dd = test::randomVec(gen, 1e-3);
  ElemMat k;
  const ElemVec r2 = residual(e, d1 + dd, &k);
  EXPECT_LT((r2 - r1 - fresh.stiffness() * dd).norm(), 1e-9 * r1.norm());
  EXPECT_LT((k - fresh.stiffness()).norm(), 1e-12 * k.norm());
  EXPECT_LT((e.mass() - fresh.mass()).norm(), 1e-14);
  EXPECT_EQ(e.shear(), shearAfter);
  // A rigid-body motion added to the committed state changes no force.
  const ElemVec rigid = (ElemVec() << 1e-2, -2e-2, 0, 1e-2, -2e-2, 0).finished();
  EXPECT_LT((residual(e, d1 + rigid) - r1).norm(), 1e-10 * r1.norm());

  // The stored energy is that of the kept forces under the new stiffness.
  residual(e, d1);
  const ElemVec x = d1 - e.stressFreeDisplacement();
  EXPECT_NEAR(e.strainEnergy(), 0.5 * x.dot(fresh.stiffness() * x), 1e-12);
}

INSTANTIATE_TEST_SUITE_P(MaterialChange, LinearFrameChange,
                         ::testing::Combine(::testing::Bool(), ::testing::Bool()));

TEST(MaterialChange, LinearFrameRefusesOtherKinematicsAndInelasticLaws) {
  const MaterialSet before = test::resultantMaterial(Kinematics::Small);
  LinearFrame e(before, {0, 1}, kX1, kX2);
  std::mt19937 gen(3);
  const ElemVec d1 = test::randomVec(gen, 1e-3);
  const ElemVec r1 = evaluateAndCommit(e, d1);

  MaterialSet finite = before;
  finite.kinematics = Kinematics::Finite;
  *finite.resEI *= 2;
  const Status st = e.setMaterial(finite, d1);
  EXPECT_FALSE(st.ok);
  EXPECT_NE(st.why.find("HINGe2joint"), std::string::npos) << st.why;

  MaterialSet hard = before;
  hard.hardening = HardeningData{1, 2, 100, 10};
  *hard.resEI *= 2;
  EXPECT_FALSE(e.setMaterial(hard, d1).ok);
  // Unchanged.
  EXPECT_LT((residual(e, d1 + d1) - 2 * r1).norm(), 1e-10 * r1.norm());
}

// The V2 section of verification.md.
using namespace test::v2;
constexpr double kL = 0.5;

MaterialSet v2(double ei = kEI) { return material(2, 1.2e6, Kinematics::Small, kMu, ei); }

// A horizontal element of length kL bent to curvature kappa (theta2 - theta1)/l,
// with some axial and shear strain.
ElemVec bent(double kappa) {
  ElemVec d;
  d << 0, 0, 0.002, 1e-5, 2e-5 + 0.5 * kL * (0.002 + 0.002 + kappa * kL), 0.002 + kappa * kL;
  return d;
}

ElemVec rotationIncrement(double dTheta2) {
  ElemVec d = ElemVec::Zero();
  d(5) = dTheta2;
  return d;
}

TEST(MaterialChange, InelasticFrameKeepsPlasticCurvatureAndUnloadsWithTheNewEI) {
  InelasticFrame e(v2(), {0, 1}, Vec2(0, 0), Vec2(kL, 0));
  const double m1 = 200;
  const double kappa1 = m1 / kEI + (m1 - kMc) / kKh1;  // on the first hardening branch
  const ElemVec d1 = bent(kappa1);
  evaluateAndCommit(e, d1);
  const SectionForces f1 = e.sectionForces();
  ASSERT_NEAR(f1.M, m1, 1e-8);

  ASSERT_TRUE(e.setMaterial(v2(2 * kEI), d1).ok);
  residual(e, d1);
  expectForcesNear(e.sectionForces(), f1, 1e-8);
  EXPECT_NEAR(e.hingeDemand(), m1 / kMu, 1e-12);

  // Unloading is elastic with the new EI; the plastic curvature is kept.
  const double dk = -1e-3;
  residual(e, d1 + rotationIncrement(dk * kL));
  EXPECT_NEAR(e.sectionForces().M, m1 + 2 * kEI * dk, 1e-8);
  // Loading goes on along the hardening law from the same hardening state:
  // dM/dkappa = EI Kh1/(EI + Kh1) with the new EI.
  const double up = 1e-5;
  residual(e, d1 + rotationIncrement(up * kL));
  EXPECT_NEAR(e.sectionForces().M, m1 + 2 * kEI * kKh1 / (2 * kEI + kKh1) * up, 1e-7);
  // The tangent is still the exact derivative of the residual.
  ElemMat k;
  const ElementKinematics kin = staticKinematics(d1 + rotationIncrement(up * kL));
  residual(e, kin.d, &k);
  const ElemMat fd = test::centralDifferenceTangent(e, kin, StepRule{}, 1e-9);
  EXPECT_LT((k - fd).norm(), 1e-5 * k.norm());
}

TEST(MaterialChange, InelasticFrameRefusesLawsItsHistoryCannotFollow) {
  InelasticFrame e(v2(), {0, 1}, Vec2(0, 0), Vec2(kL, 0));
  const ElemVec d1 = bent(200 / kEI + (200 - kMc) / kKh1);
  const ElemVec r1 = evaluateAndCommit(e, d1);

  MaterialSet lowMu = v2();
  lowMu.softening->Mu = 150;  // below the current moment of 200
  Status st = e.setMaterial(lowMu, d1);
  EXPECT_FALSE(st.ok);
  EXPECT_NE(st.why.find("Mu"), std::string::npos) << st.why;

  MaterialSet lowYield = v2();
  lowYield.hardening = HardeningData{30, 100, kKh1, kKh2};  // radius at the state: < 200
  lowYield.softening.reset();
  st = e.setMaterial(lowYield, d1);
  EXPECT_FALSE(st.ok);
  EXPECT_NE(st.why.find("yield"), std::string::npos) << st.why;

  MaterialSet finite = v2();
  finite.kinematics = Kinematics::Finite;
  EXPECT_FALSE(e.setMaterial(finite, d1).ok);
  // Nothing changed.
  EXPECT_LT((residual(e, d1) - r1).norm(), 1e-12 * r1.norm());

  // Removing the laws of an element whose hinge is inactive: the plastic
  // curvature stays, the bending is elastic from there.
  MaterialSet elastic = v2();
  elastic.hardening.reset();
  elastic.softening.reset();
  ASSERT_TRUE(e.setMaterial(elastic, d1).ok);
  residual(e, d1 + rotationIncrement(0.05 * kL));
  EXPECT_NEAR(e.sectionForces().M, 200 + kEI * 0.05, 1e-7);
  EXPECT_EQ(e.hingeDemand(), 0.0);
}

TEST(MaterialChange, ActiveHingeKeepsItsJumpAndNeedsItsSofteningLaw) {
  InelasticFrame e(v2(), {0, 1}, Vec2(0, 0), Vec2(kL, 0));
  const double kU = kMu / kEI + (kMy - kMc) / kKh1 + (kMu - kMy) / kKh2;
  evaluateAndCommit(e, bent(kU));
  e.activateHinge();
  const ElemVec d1 = bent(kU + 0.003);
  evaluateAndCommit(e, d1);
  const HingeInfo h1 = e.hinge();
  ASSERT_TRUE(h1.active);
  ASSERT_GT(h1.jump, 0);
  ASSERT_LT(h1.moment, kMu);

  MaterialSet noSoftening = v2();
  noSoftening.softening.reset();
  Status st = e.setMaterial(noSoftening, d1);
  EXPECT_FALSE(st.ok);
  EXPECT_NE(st.why.find("cannot be removed"), std::string::npos) << st.why;

  MaterialSet brittle = v2();
  brittle.softening->Ks = 4 * kKs;  // capacity at the hinge's xi below its moment
  EXPECT_FALSE(e.setMaterial(brittle, d1).ok);

  // A stronger law and a stiffer bulk: jump, softening variable and moment kept.
  MaterialSet stronger = v2(1.5 * kEI);
  stronger.softening->Mu = 300;
  ASSERT_TRUE(e.setMaterial(stronger, d1).ok);
  residual(e, d1);
  const HingeInfo h2 = e.hinge();
  EXPECT_TRUE(h2.active);
  EXPECT_NEAR(h2.jump, h1.jump, 1e-14);
  EXPECT_NEAR(h2.softening, h1.softening, 1e-14);
  EXPECT_NEAR(h2.moment, h1.moment, 1e-8);
  // Further rotation: the hinge now lies below the new capacity 300 + Ks xi, so
  // it is rigid and the bulk takes the increment with 1.5 EI.
  residual(e, d1 + rotationIncrement(1e-5 * kL));
  EXPECT_NEAR(e.hinge().jump, h1.jump, 1e-14);
  EXPECT_NEAR(e.sectionForces().M, h1.moment + 1.5 * kEI * 1e-5, 1e-7);
}

TEST(MaterialChange, ReissnerFrameKeepsForcesThroughItsInitialStrain) {
  const MaterialSet before = test::resultantMaterial(Kinematics::Finite);
  ReissnerFrame e(before, {0, 1}, kX1, kX2);
  ElemVec d1;
  d1 << 0.01, -0.02, 0.4, 0.05, 0.1, 0.9;  // large rotations
  evaluateAndCommit(e, d1);
  const SectionForces f1 = e.sectionForces();
  const ElemVec r1 = residual(e, d1);

  MaterialSet after = before;
  *after.resEI *= 2;
  *after.resEA *= 0.5;
  after.kinematics = Kinematics::Small;  // a SMALl set whose elements went through HINGe2joint
  ASSERT_TRUE(e.setMaterial(after, d1).ok);
  const ElemVec r1Again = residual(e, d1);
  EXPECT_LT((r1Again - r1).norm(), 1e-9 * r1.norm());
  expectForcesNear(e.sectionForces(), f1, 1e-9 * r1.norm());
  EXPECT_DOUBLE_EQ(e.sectionStiffness()(2), 2 * *before.resEI);
  // The moment is linear in the curvature: the increment takes the new EI.
  const double dTheta = 1e-3;
  residual(e, d1 + rotationIncrement(dTheta));
  EXPECT_NEAR(e.sectionForces().M, f1.M + 2 * *before.resEI * dTheta / e.length(), 1e-9);
}

TEST(MaterialChange, JointedElementForwardsAndKeepsTheRelativeRotation) {
  const MaterialSet before = test::resultantMaterial(Kinematics::Small);
  auto inner = std::make_unique<LinearFrame>(before, std::array{0, 2}, kX1, kX2);
  JointedElement e(std::move(inner), 1, 1);  // node 2 is the slave of master node 1
  e.setRelativeState(0.01);
  std::mt19937 gen(11);
  const ElemVec d1 = test::randomVec(gen, 1e-3);
  const ElemVec r1 = evaluateAndCommit(e, d1);
  const double psi = e.relativeRotation();
  const SectionForces f1 = e.sectionForces();

  MaterialSet after = before;
  *after.resEI *= 2;
  ASSERT_TRUE(e.setMaterial(after, d1).ok);
  const ElemVec r1Again = residual(e, d1);
  EXPECT_LT((r1Again - r1).norm(), 1e-9 * r1.norm());
  EXPECT_NEAR(e.relativeRotation(), psi, 1e-12);
  expectForcesNear(e.sectionForces(), f1, 1e-9 * r1.norm());
  EXPECT_FALSE(e.setMaterial(test::resultantMaterial(Kinematics::Finite), d1).ok);
}

// Restart files carry the stress-free displacements: an element read back
// gives the changed element's residual.
TEST(MaterialChange, RestartFilesKeepTheStressFreeDisplacement) {
  std::mt19937 gen(5);
  const ElemVec d1 = 1e-4 * test::randomVec(gen, 1.0);
  const ElemVec d2 = d1 + 1e-4 * test::randomVec(gen, 1.0);

  MaterialSet after = test::resultantMaterial(Kinematics::Small);
  *after.resEI *= 2;
  LinearFrame linear(test::resultantMaterial(Kinematics::Small), {0, 1}, kX1, kX2);
  evaluateAndCommit(linear, d1);
  ASSERT_TRUE(linear.setMaterial(after, d1).ok);
  std::stringstream ls;
  linear.writeState(ls);
  LinearFrame linearBack(after, {0, 1}, kX1, kX2);
  linearBack.readState(ls);
  EXPECT_LT((residual(linearBack, d2) - residual(linear, d2)).norm(), 1e-14);

  InelasticFrame inelastic(v2(), {0, 1}, Vec2(0, 0), Vec2(kL, 0));
  const ElemVec b1 = bent(200 / kEI + (200 - kMc) / kKh1);
  evaluateAndCommit(inelastic, b1);
  ASSERT_TRUE(inelastic.setMaterial(v2(2 * kEI), b1).ok);
  std::stringstream is;
  inelastic.writeState(is);
  InelasticFrame inelasticBack(v2(2 * kEI), {0, 1}, Vec2(0, 0), Vec2(kL, 0));
  inelasticBack.readState(is);
  const ElemVec b2 = b1 + rotationIncrement(-1e-4);
  EXPECT_LT((residual(inelasticBack, b2) - residual(inelastic, b2)).norm(), 1e-12);
  // (the offset matters: an element built afresh from the new set differs)
  InelasticFrame fresh(v2(2 * kEI), {0, 1}, Vec2(0, 0), Vec2(kL, 0));
  EXPECT_GT((residual(fresh, b2) - residual(inelastic, b2)).norm(), 1.0);
}

TEST(MaterialChange, ModelUpdateTouchesTheSetsElementsOnlyAndBumpsTheTopology) {
  Model model;
  model.resizeNodes(3);
  model.setCoord(0, Vec2(0, 0));
  model.setCoord(1, Vec2(1, 0));
  model.setCoord(2, Vec2(2, 0));
  MaterialSet a = test::resultantMaterial(Kinematics::Small);
  MaterialSet b = a;
  b.number = 2;
  model.materials()[1] = a;
  model.materials()[2] = b;
  model.setElement(
      0, std::make_unique<LinearFrame>(a, std::array{0, 1}, model.coord(0), model.coord(1)));
  model.setElement(
      1, std::make_unique<LinearFrame>(b, std::array{1, 2}, model.coord(1), model.coord(2)));

  State state;
  state.resize(3);
  state.un << 0, 0, 0, 0, 1e-3, 2e-3, 0, 3e-3, 2e-3;
  state.u = state.un;
  ElemVec d0 = state.un.segment<6>(0), d1 = state.un.segment<6>(3);
  const ElemVec r0 = evaluateAndCommit(model.element(0), d0);
  const ElemVec r1 = evaluateAndCommit(model.element(1), d1);

  MaterialSet stiffer = b;
  *stiffer.resEI *= 4;
  const int version = model.topologyVersion();
  ASSERT_TRUE(changeMaterial(model, state, stiffer).ok);
  EXPECT_GT(model.topologyVersion(), version);
  const ElemVec dd = (ElemVec() << 0, 0, 0, 0, 0, 1e-4).finished();
  const LinearFrame freshA(a, {0, 1}, model.coord(0), model.coord(1));
  const LinearFrame freshB(stiffer, {1, 2}, model.coord(1), model.coord(2));
  EXPECT_LT((residual(model.element(0), d0 + dd) - r0 - freshA.stiffness() * dd).norm(), 1e-9);
  EXPECT_LT((residual(model.element(1), d1 + dd) - r1 - freshB.stiffness() * dd).norm(), 1e-9);

  // A skipped element (just built from the new set) is left alone; a refusal
  // names the element.
  MaterialSet finite = stiffer;
  finite.kinematics = Kinematics::Finite;
  EXPECT_TRUE(changeMaterial(model, state, finite, {1}).ok);
  const Status st = changeMaterial(model, state, finite);
  EXPECT_FALSE(st.ok);
  EXPECT_EQ(st.why.rfind("element 2: ", 0), 0u) << st.why;
}

}  // namespace
}  // namespace c2d
