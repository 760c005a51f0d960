// HINGE2JOINT (elements/HingeToJoint.h) and ReissnerFrame's initial strain: a
// softening cantilever (InelasticFrame) is driven past its peak until one hinge
// is half softened, the hinge becomes a revolute joint and every element an
// elastic Reissner beam with the old section forces; the cantilever is then a
// pendulum pinned at its base that swings under a small tip force, with its
// energy conserved by the mid-point scheme.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "core/Hinge.h"
#include "core/Model.h"
#include "elements/HingeToJoint.h"
#include "elements/InelasticFrame.h"
#include "elements/JointedElement.h"
#include "elements/Joints.h"
#include "elements/ReissnerFrame.h"
#include "solvers/Analysis.h"
#include "solvers/TimeIntegrator.h"
#include "tests/unit/ElementTestSupport.h"

namespace c2d {
namespace {

using test::solveStep;

// --- ReissnerFrame initial strain ---------------------------------------------

MaterialSet reissnerMaterial() { return test::resultantMaterial(Kinematics::Finite); }

TEST(HingeToJointInitialStrain, ShiftsResultantsEnergyAndKeepsTheMidPointIdentity) {
  std::mt19937 gen(11);
  const Vec2 x1(0.1, 0.2), x2(1.3, -0.4);
  ReissnerFrame shifted(reissnerMaterial(), {0, 1}, x1, x2);
  const Vec3 e0(1e-3, -2e-3, 0.05);
  shifted.setInitialStrain(e0);
  EXPECT_EQ(shifted.initialStrain(), e0);
  const Vec3 c = shifted.sectionStiffness();
  EXPECT_EQ(c, Vec3(2.0e4, 8.0e3, 1.0e2));
  const double l = shifted.length();

  for (double alpha : {0.0, 0.15}) {
    StepRule mid = TimeIntegrator::midPoint(alpha, 0).rule(0.1);
    mid.ca = mid.av = mid.aa = 0;  // internal forces only
    const ElemVec dn = test::randomVec(gen, 0.2), d = dn + test::randomVec(gen, 0.2);
    ElemVec r;
    ElemMat k, unused;
    ASSERT_TRUE(shifted.evaluate({d, dn, ElemVec::Zero(), ElemVec::Zero()}, mid, true, r, k).ok);
    const Vec3 eps = shifted.strains(d) - e0, epsN = shifted.strains(dn) - e0;
    const SectionForces f = shifted.sectionForces();
    EXPECT_NEAR(f.N, c(0) * eps(0), 1e-10);
    EXPECT_NEAR(f.V, c(1) * eps(1), 1e-10);
    EXPECT_NEAR(f.M, c(2) * eps(2), 1e-10);
    const double w1 = 0.5 * l * eps.dot(c.asDiagonal() * eps);
    const double w0 = 0.5 * l * epsN.dot(c.asDiagonal() * epsN);
    EXPECT_NEAR(shifted.strainEnergy(), w1, 1e-14 * w1);
    EXPECT_NEAR(shifted.energy(d), w1, 1e-14 * w1);
    // r(d - dn).f = W(d) - W(dn) + alpha l dE.C.dE, with the shifted energies.
    const Vec3 dE = eps - epsN;
    EXPECT_NEAR(mid.rate(d - dn).dot(r), w1 - w0 + alpha * l * dE.dot(c.asDiagonal() * dE),
                1e-11 * std::abs(w1 - w0) + 1e-13);
    // The tangent (its geometric part sees the shifted resultants) is the
    // derivative of the residual.
    for (int j = 0; j < kElemDofs; ++j) {
      const double h = 1e-6;
      ElemVec dp = d, dm = d;
      dp(j) += h;
      dm(j) -= h;
      ElemVec rp, rm;
      ASSERT_TRUE(
          shifted.evaluate({dp, dn, ElemVec::Zero(), ElemVec::Zero()}, mid, false, rp, unused).ok);
      ASSERT_TRUE(
          shifted.evaluate({dm, dn, ElemVec::Zero(), ElemVec::Zero()}, mid, false, rm, unused).ok);
      EXPECT_LT(((rp - rm) / (2 * h) - k.col(j)).cwiseAbs().maxCoeff(),
                1e-7 * k.cwiseAbs().maxCoeff());
    }
  }
  // Static: the residual at the undeformed state is the initial-strain force
  // l B^T (-C E0), so a stress-free state is the one with E = E0.
  ElemVec r;
  ElemMat k;
  const ElemVec zero = ElemVec::Zero();
  ASSERT_TRUE(shifted.evaluate({zero, zero, zero, zero}, StepRule{}, true, r, k).ok);
  EXPECT_NEAR(shifted.sectionForces().M, -c(2) * e0(2), 1e-12);
  EXPECT_NEAR(r(5) - r(2), -2 * c(2) * e0(2), 1e-9);  // end moments -+ M
}

// --- HINGE2JOINT on a softening cantilever --------------------------------------

constexpr double kL = 2.5, kEI = 77650, kMu = 374, kKs = -18000;
constexpr int kN = 10;

MaterialSet softeningMaterial() {
  MaterialSet m = test::resultantFrame(Kinematics::Small, 4.0e6, 1.5e6, kEI, 2.5, 0.12, 0.0016);
  m.softening = SofteningData{kMu, kKs, std::nullopt};
  return m;
}

// Cantilever along x, clamped at node 0, tip node kN with a prescribed transverse
// displacement equal to the time.
Model softeningCantilever() {
  Model m;
  m.materials()[1] = softeningMaterial();
  m.resizeNodes(kN + 1);
  for (int i = 0; i <= kN; ++i) m.setCoord(i, Vec2(kL * i / kN, 0));
  for (int e = 0; e < kN; ++e)
    m.setElement(e, std::make_unique<InelasticFrame>(m.materials()[1], std::array{e, e + 1},
                                                     m.coord(e), m.coord(e + 1)));
  m.bound(0) = {1, 1, 1};
  m.bound(kN) = {0, 1, 0};
  m.disp(kN) = {0, 1.0, 0};
  return m;
}

double chordAngle(const Model& m, const State& s, int a, int b) {
  const Vec2 d = m.coord(b) + s.u.segment<2>(3 * b) - m.coord(a) - s.u.segment<2>(3 * a);
  return std::atan2(d.y(), d.x());
}

// The cantilever's load ramped past the peak (tip 0.0106) until the hinge
// moment is about Mu/2 (tip 0.030), in 30 steps, committed.
void pushPastThePeak(Analysis& an) {
  an.setLoadFunction(1, ProportionalLoad::ramp());
  an.setDt(1e-3);
  for (int s = 0; s < 30; ++s) ASSERT_TRUE(solveStep(an)) << "step " << s;
  ASSERT_TRUE(an.commit().ok);
}

TEST(HingeToJoint, TheNextStepNumbersTheNewNodes) {
  // The step after HINGE2JOINT begins with advance() on a committed state: the
  // dof map must cover the slave node the joint added before the step starts.
  Model m = softeningCantilever();
  Analysis an(m);
  ASSERT_NO_FATAL_FAILURE(pushPastThePeak(an));
  ASSERT_EQ(hingeToJoint(m, an.state()).size(), 1u);
  ASSERT_TRUE(an.advance());
  EXPECT_EQ(an.assembler().dofs().numNodes(), m.numNodes());
  EXPECT_EQ(an.state().u.size(), 3 * m.numNodes());
}

TEST(HingeToJoint, SoftenedCantileverBecomesAPendulumWithContinuousSectionForces) {
  Model m = softeningCantilever();
  Analysis an(m);
  ASSERT_NO_FATAL_FAILURE(pushPastThePeak(an));

  int activeHinges = 0;
  HingeInfo hinge;
  for (int e = 0; e < kN; ++e) {
    const HingeInfo h = dynamic_cast<const HingeCarrier&>(m.element(e)).hinge();
    if (h.active) {
      ++activeHinges;
      hinge = h;
      EXPECT_EQ(e, 0);  // the base element carries the largest moment
    }
  }
  ASSERT_EQ(activeHinges, 1);
  EXPECT_FALSE(hinge.failed);
  EXPECT_NEAR(std::abs(hinge.moment), kMu / 2, 0.15 * kMu);
  EXPECT_NEAR(std::abs(hinge.jump), (kMu - std::abs(hinge.moment)) / -kKs, 1e-9);

  std::vector<SectionForces> before(kN);
  for (int e = 0; e < kN; ++e) before[e] = m.element(e).sectionForces();
  const Eigen::VectorXd uBefore = an.state().u;

  const std::vector<CreatedJoint> created = hingeToJoint(m, an.state());
  ASSERT_EQ(created.size(), 1u);
  const CreatedJoint& cj = created[0];
  EXPECT_EQ(cj.element, 0);
  EXPECT_EQ(cj.slaveEnd, 0);  // the end at the clamp: larger end moment
  EXPECT_EQ(cj.master, 0);
  EXPECT_EQ(cj.slave, kN + 1);
  EXPECT_EQ(cj.position, 0.5);
  EXPECT_EQ(cj.jump, hinge.jump);
  EXPECT_EQ(cj.relativeRotation, hinge.jump);  // joint at element node 1: +alpha
  EXPECT_EQ(m.numNodes(), kN + 2);
  ASSERT_EQ(m.joints().size(), 1u);
  EXPECT_EQ(m.joints()[0].master, 0);
  EXPECT_EQ(m.joints()[0].slave, kN + 1);
  EXPECT_EQ(m.joints()[0].form, JointForm::Condensed);
  EXPECT_EQ(m.coord(kN + 1), m.coord(0));
  EXPECT_EQ(m.bound(kN + 1), (std::array<int, 3>{0, 0, 0}));

  // Every element is an elastic Reissner beam; the first one behind the joint.
  auto* je = dynamic_cast<JointedElement*>(&m.element(0));
  ASSERT_NE(je, nullptr);
  EXPECT_EQ(je->slaveNode(), kN + 1);
  EXPECT_EQ(je->nodes(), (std::array<int, 2>{0, 1}));
  EXPECT_EQ(je->relativeRotation(), hinge.jump);
  const auto* hingeFrame = dynamic_cast<const ReissnerFrame*>(&je->inner());
  ASSERT_NE(hingeFrame, nullptr);
  for (int e = 1; e < kN; ++e)
    EXPECT_NE(dynamic_cast<const ReissnerFrame*>(&m.element(e)), nullptr);
  EXPECT_EQ(m.material(1)->kinematics, Kinematics::Small);  // the model's sets are untouched

  // Section forces carried over exactly.
  for (int e = 0; e < kN; ++e) {
    const SectionForces f = m.element(e).sectionForces();
    EXPECT_NEAR(f.N, before[e].N, 1e-9 * kMu) << "element " << e;
    EXPECT_NEAR(f.V, before[e].V, 1e-9 * kMu) << "element " << e;
    EXPECT_NEAR(f.M, before[e].M, 1e-9 * kMu) << "element " << e;
  }
  // Without hardening there is no plastic curvature: the hinge element's
  // curvature (theta2 - theta1 - psi_r)/l is the old elastic one exactly, which
  // checks the sign of psi_r (the other sign would leave 2 alpha/l = 0.1).
  EXPECT_NEAR(hingeFrame->initialStrain()(2), 0, 1e-12);
  for (int e = 1; e < kN; ++e)
    EXPECT_NEAR(dynamic_cast<const ReissnerFrame&>(m.element(e)).initialStrain()(2), 0, 1e-12);

  // State: the slave moves with the master and is rotated by psi_r; committed = trial.
  const State& s = an.state();
  EXPECT_EQ(s.u.size(), 3 * (kN + 2));
  EXPECT_EQ(s.u.head(3 * (kN + 1)), uBefore);
  EXPECT_EQ(s.u.segment<2>(3 * (kN + 1)), s.u.segment<2>(0));
  EXPECT_EQ(s.u(3 * (kN + 1) + 2), s.u(2) + hinge.jump);
  EXPECT_EQ(s.un, s.u);
  EXPECT_EQ(s.vn, s.v);

  // A second call finds no active hinge and changes nothing.
  const int version = m.topologyVersion();
  EXPECT_TRUE(hingeToJoint(m, an.state()).empty());
  EXPECT_EQ(m.numNodes(), kN + 2);
  EXPECT_EQ(m.joints().size(), 1u);
  EXPECT_EQ(&je->inner(), hingeFrame);
  EXPECT_EQ(m.topologyVersion(), version);

  // Collapse phase: free the tip, push it up with a small force (5 kN, 1/30 of the
  // peak load) and let the mechanism swing.
  m.bound(kN) = {0, 0, 0};
  m.disp(kN) = {0, 0, 0};
  const double force = 5.0;
  m.force(kN) = {0, force, 0};
  m.bumpTopology();
  an.setLoadFunction(1, ProportionalLoad::table({{0.0, 1.0}}));
  an.setIntegrator(TimeIntegrator::midPoint(0, 0));
  const double dt = 0.005;
  an.setDt(dt);
  const double phi0 = chordAngle(m, an.state(), 0, kN);
  const double e0 = an.energy().total();
  double worst = 0;
  const int steps = 80;
  for (int st = 0; st < steps; ++st) {
    ASSERT_TRUE(solveStep(an)) << "step " << st;
    ASSERT_TRUE(an.commit().ok);
    worst = std::max(worst, std::abs(an.energy().total() - e0));
  }
  const double phi = chordAngle(m, an.state(), 0, kN);

  // Rigid pendulum about the pin under a vertical tip force:
  // J phi'' = F L cos(phi), J = rhoA L^3/3 + rhoI L (consistent mass, exact for
  // a rigid rotation), integrated with RK4.
  const MaterialSet& mat = *m.material(1);
  const double inertia = mat.rhoA() * kL * kL * kL / 3 + mat.rhoI() * kL;
  double y = phi0, yd = 0;
  const int sub = 1000;
  const double h = steps * dt / sub;
  auto acc = [&](double p) { return force * kL * std::cos(p) / inertia; };
  for (int i = 0; i < sub; ++i) {
    const double k1 = yd, l1 = acc(y);
    const double k2 = yd + 0.5 * h * l1, l2 = acc(y + 0.5 * h * k1);
    const double k3 = yd + 0.5 * h * l2, l3 = acc(y + 0.5 * h * k2);
    const double k4 = yd + h * l3, l4 = acc(y + h * k3);
    y += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    yd += h / 6 * (l1 + 2 * l2 + 2 * l3 + l4);
  }
  EXPECT_GT(phi - phi0, 0.5);  // a mechanism: an elastic cantilever would turn 1e-4 rad
  // Within the elastic spring-back released by the joint (M L/(2 EI) ~ 1e-3 rad).
  EXPECT_NEAR(phi - phi0, y - phi0, 2e-3) << "rigid pendulum " << y - phi0;
  const double scale = an.energy().kinetic;
  EXPECT_LT(worst, 1e-10 * scale) << "kinetic " << scale;
  // The joint carries the whole turn of the cantilever.
  syncSlaveNodes(m, an.state());
  EXPECT_NEAR(an.state().u(3 * (kN + 1) + 2), je->slaveRotation(), 1e-12);
  EXPECT_GT(je->relativeRotation() - hinge.jump, 0.5);
}

// A member whose hinge fails after it already carries a joint at one end (the
// joint of its first failure) gets the new joint at its other end: it becomes
// a link pinned at both ends, whose inner rotations follow its chord, instead
// of keeping the failed hinge inside (nothing would then resist its two ends
// turning against each other: the member would fold through any angle). The
// switch keeps the first joint's relative rotation and rates as the motion
// left them, and the member's section forces and stored energy.
// With rigid end zones on that member (offsets) its joints are at the faces:
// each face stays where the master's arm puts it through the switch.
void memberFailedTwice(const std::array<double, 2>& offsets) {
  const MaterialSet mat = test::hingedRodMaterial(0.6);
  Model m;
  m.materials()[1] = mat;
  m.resizeNodes(4);
  for (int i = 0; i < 4; ++i) m.setCoord(i, Vec2(1.0 * i, 0));
  for (int e = 0; e < 3; ++e)
    m.setElement(e, std::make_unique<ReissnerFrame>(mat, std::array{e, e + 1}, m.coord(e),
                                                    m.coord(e + 1),
                                                    e == 1 ? offsets : std::array{0.0, 0.0}));
  // Element 1 on a slave of node 1: the joint of its first failure.
  const int first = m.addNode(m.coord(1));
  m.element(1).setNodes({first, 2});
  m.joints().push_back(Joint{1, first, JointForm::Condensed});
  ASSERT_EQ(installJoints(m), 1);
  // Its hinge has failed since: no moment, whatever the jump.
  HingedBendingState failed;
  failed.hingeActive = failed.hingeFailed = true;
  failed.jump.alpha = failed.jump.xi = 0.05;
  dynamic_cast<ReissnerFrame&>(innermost(m.element(1))).setSection(failed);
  // A moving state in which the first joint's relative rotation is not the
  // one a static solve would give.
  State s;
  s.resize(m.numNodes());
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.02, 0.02);
  for (Eigen::Index i = 0; i < s.u.size(); ++i) {
    s.u[i] = u(rng);
    s.v[i] = 10 * u(rng);
  }
  s.un = s.u;
  s.vn = s.v;
  jointedElements(m).front()->setRelativeState(0.2, 0.5, 0, Vec2(0.1, -0.3), Vec2(0, 0));
  syncSlaveNodes(m, s);
  // The slave node carries the wrapped element's end: the master's motion
  // plus the shift of a joint at a face, and the shift's velocity.
  const JointedElement& firstJoint = *jointedElements(m).front();
  EXPECT_EQ(s.u.segment<2>(3 * first), s.u.segment<2>(3) + firstJoint.shiftAt(s.u[5], 0.2));
  EXPECT_EQ(s.v.segment<2>(3 * first),
            s.v.segment<2>(3) + (firstJoint.hasArm() ? Vec2(0.1, -0.3) : Vec2::Zero()));
  const StepRule statics{};
  auto innerEnergy = [&] {
    ElemVec r;
    ElemMat k;
    Element& in = innermost(m.element(1));
    EXPECT_TRUE(in.evaluate(innermostKinematics(m.element(1), s), statics, false, r, k));
    return std::pair{in.strainEnergy(), in.sectionForces()};
  };
  // The inner element's face at `end` less where the master's arm puts it.
  auto faceMiss = [&](int end, int master) {
    const auto& frame = dynamic_cast<const ReissnerFrame&>(innermost(m.element(1)));
    const ElementKinematics in = innermostKinematics(m.element(1), s);
    const Vec2 face = in.d.segment<2>(3 * end) + frame.rigidEnds().armMotion(end, in.d(3 * end + 2));
    const double psiM = s.u[3 * master + 2];
    const Vec2 node = s.u.segment<2>(3 * master);
    return (face - node - frame.rigidEnds().armMotion(end, psiM)).norm();
  };
  EXPECT_LT(faceMiss(0, 1), 1e-15);
  const auto [energyBefore, forcesBefore] = innerEnergy();
  const double alpha = dynamic_cast<const HingeCarrier&>(innermost(m.element(1))).hinge().jump;

  const std::vector<CreatedJoint> created = jointFailedHinges(m, s);
  ASSERT_EQ(created.size(), 1u);
  EXPECT_EQ(created[0].element, 1);
  EXPECT_EQ(created[0].slaveEnd, 1);  // the end without a joint
  EXPECT_EQ(created[0].master, 2);
  EXPECT_EQ(created[0].slave, 5);
  EXPECT_EQ(created[0].relativeRotation, -alpha);
  // Wrapped at both ends; the first joint as the motion left it.
  auto* outer = dynamic_cast<JointedElement*>(&m.element(1));
  ASSERT_NE(outer, nullptr);
  auto* inner = dynamic_cast<JointedElement*>(&outer->inner());
  ASSERT_NE(inner, nullptr);
  const JointedElement* atFirst = outer->slaveNode() == first ? outer : inner;
  const JointedElement* atNew = outer->slaveNode() == first ? inner : outer;
  EXPECT_EQ(atFirst->slaveNode(), first);
  EXPECT_EQ(atFirst->committedRelativeRotation(), 0.2);
  EXPECT_EQ(atFirst->committedRelativeVelocity(), 0.5);
  EXPECT_EQ(atNew->slaveNode(), 5);
  EXPECT_EQ(atNew->committedRelativeRotation(), -alpha);
  // The hinge's capacity is fresh, the section forces and energy unchanged.
  const auto& frame = dynamic_cast<const ReissnerFrame&>(innermost(m.element(1)));
  EXPECT_FALSE(frame.hinge().active);
  const auto [energyAfter, forcesAfter] = innerEnergy();
  EXPECT_NEAR(energyAfter, energyBefore, 1e-12 * std::abs(energyBefore));
  EXPECT_NEAR(forcesAfter.N, forcesBefore.N, 1e-9 * std::abs(forcesBefore.N));
  EXPECT_NEAR(forcesAfter.V, forcesBefore.V, 1e-9 * std::abs(forcesBefore.N));
  EXPECT_NEAR(forcesAfter.M, 0, 1e-9);
  EXPECT_LT(faceMiss(0, 1), 1e-15);
  EXPECT_LT(faceMiss(1, 2), 1e-15);

  // A link pinned at both ends opens no hinge and gets no third joint: a
  // failed hinge there leaves it as it is.
  dynamic_cast<ReissnerFrame&>(innermost(m.element(1))).setSection(failed);
  const int version = m.topologyVersion();
  EXPECT_TRUE(jointFailedHinges(m, s).empty());
  EXPECT_EQ(m.topologyVersion(), version);
}

TEST(JointFailedHinges, AMemberFailedTwiceBecomesALinkPinnedAtBothEnds) {
  memberFailedTwice({0.0, 0.0});
}

TEST(JointFailedHinges, AMemberWithRigidZonesFailedTwiceIsPinnedAtItsFaces) {
  memberFailedTwice({0.2, 0.3});
}

// A member breaks where it carries a moment to the rest of the model, never
// at a free end: in a free piece of two elements whose end element's hinge
// has failed, the joint goes to the middle node, not to the free end (no
// joint, nor a jump taken by the free node's rotation), and the piece becomes
// two pinned there. The other element then breaks at the pin too when its
// hinge fails; the first one, pinned and free, has no end left: a failed hinge
// of its own stays as it is, with no fresh capacity.
TEST(JointFailedHinges, AFreePieceBreaksWhereItCarriesAMomentNeverAtAFreeEnd) {
  const MaterialSet mat = test::hingedRodMaterial(0.6);
  Model m;
  m.materials()[1] = mat;
  m.resizeNodes(3);
  for (int i = 0; i < 3; ++i) m.setCoord(i, Vec2(1.0 * i, 0.1 * i));
  for (int e = 0; e < 2; ++e)
    m.setElement(e, std::make_unique<ReissnerFrame>(mat, std::array{e, e + 1}, m.coord(e),
                                                    m.coord(e + 1)));
  HingedBendingState failed;
  failed.hingeActive = failed.hingeFailed = true;
  failed.jump.alpha = failed.jump.xi = 0.4;
  dynamic_cast<ReissnerFrame&>(m.element(0)).setSection(failed);
  State s;
  s.resize(m.numNodes());
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.02, 0.02);
  for (Eigen::Index i = 0; i < s.u.size(); ++i) s.u[i] = u(rng);
  s.un = s.u;
  const std::vector<CreatedJoint> created = jointFailedHinges(m, s);
  ASSERT_EQ(created.size(), 1u);
  EXPECT_EQ(created[0].element, 0);
  EXPECT_EQ(created[0].master, 1);  // the middle node, not the free end 0
  EXPECT_EQ(created[0].slaveEnd, 1);
  EXPECT_EQ(created[0].slave, 3);
  EXPECT_EQ(created[0].relativeRotation, -created[0].jump);
  EXPECT_EQ(s.u[2], s.un[2]);  // the free end's rotation as it was
  EXPECT_FALSE(dynamic_cast<const HingeCarrier&>(innermost(m.element(0))).hinge().active);

  // Element 1, at the pin and at the free end 2: a joint at the pin.
  dynamic_cast<ReissnerFrame&>(m.element(1)).setSection(failed);
  const std::vector<CreatedJoint> second = jointFailedHinges(m, s);
  ASSERT_EQ(second.size(), 1u);
  EXPECT_EQ(second[0].element, 1);
  EXPECT_EQ(second[0].master, 1);
  EXPECT_EQ(second[0].slaveEnd, 0);
  // Element 0: its end 1 has its joint, its end 0 is free.
  dynamic_cast<ReissnerFrame&>(innermost(m.element(0))).setSection(failed);
  const int version = m.topologyVersion();
  EXPECT_TRUE(jointFailedHinges(m, s).empty());
  EXPECT_EQ(m.topologyVersion(), version);
  const HingeInfo kept = dynamic_cast<const HingeCarrier&>(innermost(m.element(0))).hinge();
  EXPECT_TRUE(kept.active && kept.failed);
  // Restrained, or loaded by a moment, a node carries one with one member.
  const std::vector<int> attached = nodeAttachments(m);
  EXPECT_EQ(attached, (std::vector<int>{1, 2, 1, 2, 2}));
  EXPECT_TRUE(freeEnd(m, 2, attached[2]));
  m.force(2)[2] = 1;
  EXPECT_FALSE(freeEnd(m, 2, attached[2]));
  m.force(2)[2] = 0;
  m.bound(2)[2] = 1;
  EXPECT_FALSE(freeEnd(m, 2, attached[2]));
}

// A member broken at a joint: next to it the moment grows as V x from zero, so
// with the shear a member carries bounded (SOFTening's Lb ~ Mu/Vu) no second
// joint forms within Lb of it, whatever the mesh. Without Lb the mesh's node
// spacing is the shortest piece: a rod of 0.25 m elements broke into pieces of
// one element next to each broken section, and the six-storey fall ruptured
// twice the joints at 288 elements as at 84.
// ruptured: the joint at the middle has ruptured, its two pieces' ends there
// free.
std::vector<CreatedJoint> failNextToAJoint(double lb, double h, int failing,
                                           bool ruptured = false) {
  MaterialSet mat = test::hingedRodMaterial(0.6);
  mat.softening->pieceLength = lb;
  Model m;
  m.materials()[1] = mat;
  const int n = static_cast<int>(std::lround(2.0 / h));  // a 2 m rod
  m.resizeNodes(n + 1);
  for (int i = 0; i <= n; ++i) m.setCoord(i, Vec2(h * i, 0));
  for (int e = 0; e < n; ++e)
    m.setElement(e, std::make_unique<ReissnerFrame>(mat, std::array{e, e + 1}, m.coord(e),
                                                    m.coord(e + 1)));
  m.bound(0)[2] = m.bound(n)[2] = 1;  // both ends held: no free end
  // The joint of an earlier failure at the middle node (x = 1 m).
  const int mid = n / 2;
  const int slave = m.addNode(m.coord(mid));
  m.element(mid).setNodes({slave, mid + 1});
  if (!ruptured) {
    m.joints().push_back(Joint{mid, slave, JointForm::Condensed});
    EXPECT_EQ(installJoints(m), 1);
  }
  HingedBendingState failed;
  failed.hingeActive = failed.hingeFailed = true;
  failed.jump.alpha = failed.jump.xi = 0.4;
  dynamic_cast<ReissnerFrame&>(innermost(m.element(failing))).setSection(failed);
  State s;
  s.resize(m.numNodes());
  return jointFailedHinges(m, s);
}

TEST(JointFailedHinges, NoJointWithinTheShortestPieceOfAnIntactJoint) {
  // Elements of 0.25 m: the one next to the joint (x = 1.25-1.5 m) fails.
  const std::vector<CreatedJoint> anywhere = failNextToAJoint(0, 0.25, 5);
  ASSERT_EQ(anywhere.size(), 1u);  // without Lb: a piece of 0.25-0.5 m
  EXPECT_TRUE(failNextToAJoint(0.6, 0.25, 5).empty());  // both ends within 0.6 m
  // Elements of 0.5 m: the one at the joint (x = 1-1.5 m) fails again: without
  // Lb a link of 0.5 m, with it no joint (its other end at 0.5 m).
  EXPECT_EQ(failNextToAJoint(0, 0.5, 2).size(), 1u);
  EXPECT_TRUE(failNextToAJoint(0.6, 0.5, 2).empty());
  // Farther out (x = 1.5-1.75 m, 0.25 m elements): the end beyond Lb breaks.
  const std::vector<CreatedJoint> beyond = failNextToAJoint(0.6, 0.25, 6);
  ASSERT_EQ(beyond.size(), 1u);
  EXPECT_EQ(beyond[0].master, 7);  // x = 1.75 m, not node 6 at 0.5 m
}

// A ruptured joint leaves free ends, which carry no moment either: the failed
// hinges it kept from jointing stay failed instead of becoming joints beyond
// thetaR that rupture at once, each setting free a piece shorter than Lb (the
// six-storey fall at 288 elements: 10-15 of its 46-59 ruptures).
TEST(JointFailedHinges, NoJointWithinTheShortestPieceOfAFreeEnd) {
  // The element next to the right piece's free end (x = 1.25-1.5 m) fails.
  const std::vector<CreatedJoint> anywhere = failNextToAJoint(0, 0.25, 5, true);
  ASSERT_EQ(anywhere.size(), 1u);  // without Lb: a piece of 0.25-0.5 m
  EXPECT_TRUE(failNextToAJoint(0.6, 0.25, 5, true).empty());
  // The left piece (x = 0.25-0.5 m): node 2 lies within 0.6 m of its free
  // end at x = 1 m, node 1 beyond.
  const std::vector<CreatedJoint> left = failNextToAJoint(0.6, 0.25, 1, true);
  ASSERT_EQ(left.size(), 1u);
  EXPECT_EQ(left[0].master, 1);
  // Farther out (x = 1.5-1.75 m): the end beyond Lb breaks.
  const std::vector<CreatedJoint> beyond = failNextToAJoint(0.6, 0.25, 6, true);
  ASSERT_EQ(beyond.size(), 1u);
  EXPECT_EQ(beyond[0].master, 7);
}

}  // namespace
}  // namespace c2d
