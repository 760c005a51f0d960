// Hinge events of the static driver (Analysis) on the V2 cantilever of
// verification.md: tip rotation imposed, the step that takes the moment past Mu
// is cut where it reaches Mu, exactly one hinge opens under the uniform moment
// (or in the weakened element), and the rest of the step converges on the
// softening branch.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>

#include "tests/unit/V2Material.h"
#include "core/Element.h"
#include "core/Hinge.h"
#include "core/Model.h"
#include "elements/InelasticFrame.h"
#include "solvers/Analysis.h"

namespace c2d {
namespace {

using namespace test::v2;
constexpr double kL = 2.5;

MaterialSet v2Set(int number, double Mu) { return material(number, 1.25e6, Kinematics::Small, Mu); }

// n elements along x, clamped at node 0, tip rotation theta = thetaMax * t;
// element `weak` (or none: -1) has the ultimate moment muWeak.
Model cantilever(int n, double thetaMax, int weak = -1, double muWeak = kMu) {
  Model m;
  m.materials()[1] = v2Set(1, kMu);
  m.materials()[2] = v2Set(2, muWeak);
  m.resizeNodes(n + 1);
  for (int i = 0; i <= n; ++i) m.setCoord(i, Vec2(kL * i / n, 0));
  for (int e = 0; e < n; ++e)
    m.setElement(e, std::make_unique<InelasticFrame>(m.materials()[e == weak ? 2 : 1], std::array{e, e + 1},
                                                     m.coord(e), m.coord(e + 1)));
  m.bound(0) = {1, 1, 1};
  m.bound(n) = {0, 0, 1};
  m.disp(n) = {0, 0, thetaMax};
  return m;
}

// One TIME + Newton loop; the converged step is left uncommitted (as TANG leaves it).
int solveStep(Analysis& an) {
  if (!an.advance()) return -1;
  IterationInfo info;
  for (int i = 1; i <= 10; ++i) {
    if (!an.iterate(false, true, info)) return -1;
    if (info.converged) return i;
  }
  return -1;
}

struct Hinges {
  int count = 0, element = -1;
  HingeInfo info;
};

Hinges activeHinges(const Model& m) {
  Hinges h;
  for (int e = 0; e < m.numElements(); ++e) {
    const HingeInfo i = dynamic_cast<const HingeCarrier&>(m.element(e)).hinge();
    if (!i.active) continue;
    ++h.count;
    h.element = e;
    h.info = i;
  }
  return h;
}

// Tip moment: the reaction at the prescribed tip rotation.
double tipMoment(Analysis& an, int n) {
  Eigen::VectorXd r;
  EXPECT_TRUE(an.reactions(r));
  return r[3 * n + 2];
}

// theta(M) past the peak: L (kp + M/EI) + (M - Mu)/Ks, kp the plastic curvature at Mu.
double postPeakMoment(double theta, double mu) {
  const double kp = kappaOf(mu) - mu / kEI;
  return (theta - kL * kp + mu / kKs) / (kL / kEI + 1 / kKs);
}

TEST(HingeEvent, UniformMomentOpensExactlyOneHingeAtTheLocatedLevel) {
  for (int n : {5, 10, 20}) {
    const double thetaF = kL * (kappaOf(kMu) - kMu / kEI) + kMu / -kKs;  // M = 0
    Model m = cantilever(n, thetaF);
    Analysis an(m);
    an.setLoadFunction(1, ProportionalLoad::ramp());
    double activationTheta = -1;
    an.onHingeActivated = [&](int, const HingeInfo&) { activationTheta = an.state().u[3 * n + 2]; };
    an.setDt(0.1);
    for (int s = 1; s <= 10; ++s) {
      // Two iterations per step (the predictor and one correction); the last
      // step holds the event and complete failure.
      const int its = solveStep(an);
      ASSERT_GT(its, 0) << "n = " << n << ", step " << s;
      if (s < 10) {
        EXPECT_EQ(its, 2) << "n = " << n << ", step " << s;
      }
      const double theta = thetaF * s / 10, M = tipMoment(an, n);
      const Hinges h = activeHinges(m);
      if (theta < kL * kappaOf(kMu)) {
        EXPECT_EQ(h.count, 0);
        EXPECT_NEAR(kL * kappaOf(M), theta, 1e-12);
      } else {
        ASSERT_EQ(h.count, 1) << "n = " << n;
        EXPECT_EQ(h.element, 0);  // ties to round-off go to the lowest element number
        EXPECT_NEAR(M, std::max(0.0, postPeakMoment(theta, kMu)), 1e-6) << "step " << s;
        EXPECT_NEAR(h.info.moment, M, 1e-6);
      }
    }
    EXPECT_NEAR(activationTheta, 0.0835350, 5e-8);
    EXPECT_NEAR(activationTheta, kL * kappaOf(kMu), 1e-9);
    // At theta_f the jump is Mu/|Ks| (the moment is zero to the location band).
    EXPECT_NEAR(activeHinges(m).info.jump, kMu / -kKs, 1e-9);
    EXPECT_NEAR(tipMoment(an, n), 0, 1e-6);
  }
}

TEST(HingeEvent, WeakenedElementCarriesTheHinge) {
  const int n = 10, weak = 6;
  const double muW = 270, thetaMax = 0.05;
  Model m = cantilever(n, thetaMax, weak, muW);
  Analysis an(m);
  an.setLoadFunction(1, ProportionalLoad::ramp());
  an.setDt(0.05);
  for (int s = 1; s <= 20; ++s) {
    const double theta = thetaMax * s / 20;
    // Two iterations per step, twice that in the step of the event: two up to
    // the converged end of the step that detects it, two for the rest after
    // the hinge opened at the located level.
    const int its = solveStep(an);
    const bool event = theta > kL * kappaOf(muW) && theta - thetaMax / 20 < kL * kappaOf(muW);
    EXPECT_EQ(its, event ? 4 : 2) << "step " << s;
    if (theta > kL * kappaOf(muW)) {
      const Hinges h = activeHinges(m);
      ASSERT_EQ(h.count, 1);
      EXPECT_EQ(h.element, weak);
      EXPECT_NEAR(tipMoment(an, n), std::max(0.0, postPeakMoment(theta, muW)), 1e-6);
    }
  }
}

// A dynamic step (mid-point scheme) in which the weakened element reaches Mu:
// the event is located in the band and costs few iterations. Each trial of the
// location starts from the chord between the bracket's converged ends
// (HingeEvents::solveBetween), a correction or two from the solution; from the
// committed state every trial took a whole solve.
TEST(HingeEvent, DynamicEventTrialsStartFromTheBracket) {
  const int n = 10, weak = 6;
  const double muW = 270, thetaMax = 0.05;
  Model m = cantilever(n, thetaMax, weak, muW);
  for (int e = 0; e < n; ++e) {
    MaterialSet mat = m.materials()[e == weak ? 2 : 1];
    mat.density = 2.5;
    mat.A = 0.12;
    mat.I = 1.6e-3;
    m.setElement(
        e, std::make_unique<InelasticFrame>(mat, std::array{e, e + 1}, m.coord(e), m.coord(e + 1)));
  }
  Analysis an(m);
  an.setLoadFunction(1, ProportionalLoad::ramp());
  an.setIntegrator(TimeIntegrator::midPoint(0, 0));
  an.setDt(0.05);
  double demand = -1;
  an.onHingeActivated = [&](int, const HingeInfo& h) { demand = std::abs(h.moment) / muW; };
  int eventIterations = -1;
  for (int s = 1; s <= 20 && demand < 0; ++s) {
    const int before = an.totalIterations();
    ASSERT_TRUE(an.advance());
    IterationInfo info;
    // Up to 35 iterations where Newton's method cycles on the hardening kinks.
    for (int i = 0; i < 60 && !info.converged; ++i) ASSERT_TRUE(an.iterate(false, true, info));
    ASSERT_TRUE(info.converged) << "step " << s;
    if (demand >= 0) eventIterations = an.totalIterations() - before;
  }
  ASSERT_GE(demand, 1.0);
  EXPECT_LE(demand, 1.0 + 1e-12);
  const Hinges h = activeHinges(m);
  ASSERT_EQ(h.count, 1);
  EXPECT_EQ(h.element, weak);
  // 48 iterations in the step of the event (73 with every trial from the
  // committed state).
  EXPECT_LE(eventIterations, 55);
}

// A demand that jumps past 1 within a step (an RC member whose axial force
// reaches the bars' yield or the squash load, where Mu(N) falls to its floor):
// a spring along x whose "moment" k u has the capacity Mu0 up to the
// stretch uJ and Mu0/1.5 beyond, so that the demand jumps from 0.9 to 1.35
// at uJ. Its hinge is one that may open below its capacity (a member's end
// hinge: rigid-plastic, rigid until the force reaches the capacity). The
// locator halves the bracket to round-off; the hinge opens at the bracket's
// lower end and the rest of the step returns the force to the capacity, so
// that no committed state carries more than its capacity.
class JumpingCapacitySpring final : public Element, public HingeCarrier {
 public:
  JumpingCapacitySpring(std::array<int, 2> nodes, double k, double mu0, double uJ)
      : nodes_(nodes), k_(k), mu0_(mu0), uJ_(uJ) {}
  std::array<int, 2> nodes() const override { return nodes_; }
  void setNodes(const std::array<int, 2>& n) override { nodes_ = n; }
  int materialNumber() const override { return 1; }
  std::string typeName() const override { return "test-spring"; }
  double capacity(double u) const { return u < uJ_ ? mu0_ : mu0_ / 1.5; }
  Status evaluate(const ElementKinematics& kin, const StepRule&, bool wantTangent, ElemVec& r,
                  ElemMat& k) override {
    const double u = kin.d(3) - kin.d(0);
    trial_.u = u;
    trial_.p = committed_.p;
    double kt = k_;
    trial_.force = k_ * (u - trial_.p);
    if (trial_.open && std::abs(trial_.force) > capacity(u)) {  // slips at the capacity
      trial_.force = std::copysign(capacity(u), trial_.force);
      trial_.p = u - trial_.force / k_;
      kt = 0;
    }
    r = ElemVec::Zero();
    r(0) = -trial_.force;
    r(3) = trial_.force;
    if (wantTangent) {
      k = ElemMat::Zero();
      k(0, 0) = k(3, 3) = kt;
      k(0, 3) = k(3, 0) = -kt;
    }
    return Status::success();
  }
  ElemMat mass() const override { return ElemMat::Zero(); }
  ElemVec bodyLoad(const Vec2&) const override { return ElemVec::Zero(); }
  void commit() override { committed_ = trial_; }
  void revert() override { trial_ = committed_; }
  double strainEnergy() const override {
    return 0.5 * trial_.force * trial_.force / k_;
  }
  SectionForces sectionForces() const override { return {trial_.force, 0, 0}; }
  // |force| / capacity at the trial state.
  double ratio() const { return std::abs(trial_.force) / capacity(trial_.u); }
  double hingeDemand() const override { return trial_.open ? 0.0 : ratio(); }
  void activateHinge() override { trial_.open = true; }
  int earlyEnd() const override { return trial_.open ? -1 : 0; }
  void activateHingeAt(int) override { trial_.open = true; }
  HingeInfo hinge() const override {
    HingeInfo h;
    h.active = trial_.open;
    h.moment = trial_.force;
    h.ultimate = capacity(trial_.u);
    return h;
  }

 private:
  struct State {
    double u = 0, p = 0, force = 0;
    bool open = false;
  };
  std::array<int, 2> nodes_;
  double k_, mu0_, uJ_;
  State trial_, committed_;
};

TEST(HingeEvent, DemandJumpingPastOneOpensTheEndHingeBelowItsCapacity) {
  // Node 0 fixed, node 1 free along x, node 2 pulled along x: the jumping
  // spring (k = 1000, Mu0 = 10, uJ = 0.009: demand 0.9 -> 1.35) in series
  // with a stiff elastic one.
  Model m;
  m.resizeNodes(3);
  for (int i = 0; i < 3; ++i) m.setCoord(i, Vec2(i, 0));
  m.setElement(0, std::make_unique<JumpingCapacitySpring>(std::array{0, 1}, 1000.0, 10.0, 0.009));
  m.setElement(1, std::make_unique<JumpingCapacitySpring>(std::array{1, 2}, 1e6, 1e9, 1e9));
  m.bound(0) = {1, 1, 1};
  m.bound(1) = {0, 1, 1};
  m.bound(2) = {1, 1, 1};
  m.disp(2) = {0.02, 0, 0};
  Analysis an(m);
  an.setLoadFunction(1, ProportionalLoad::ramp());
  const auto& spring = dynamic_cast<const JumpingCapacitySpring&>(m.element(0));
  int opened = 0;
  double ratioAtOpening = -1, uAtOpening = -1;
  an.onHingeActivated = [&](int e, const HingeInfo&) {
    EXPECT_EQ(e, 0);
    ++opened;
    ratioAtOpening = spring.ratio();  // the committed state where it opens
    uAtOpening = an.state().u[3];
  };
  an.setDt(0.1);
  double largest = 0;
  for (int s = 1; s <= 10; ++s) {
    ASSERT_GT(solveStep(an), 0) << "step " << s;
    largest = std::max(largest, spring.ratio());
  }
  EXPECT_EQ(opened, 1);
  // Opened at the jump, below its capacity (the lower end of a bracket
  // halved to round-off), never carrying more than its capacity after.
  EXPECT_NEAR(uAtOpening, 0.009, 1e-12);
  EXPECT_LT(ratioAtOpening, 1.0);
  EXPECT_GT(ratioAtOpening, 0.899);
  EXPECT_LE(largest, 1.0 + 1e-10);
  EXPECT_NEAR(spring.sectionForces().N, 10.0 / 1.5, 1e-9);
}

}  // namespace
}  // namespace c2d

namespace c2d {
namespace {

// Two hinges reaching their capacities a round-off fraction of a dynamic step
// apart: a mass (1 t, node 1, along x) pushed by a ramped force F = 100 t kN
// against two parallel capacity springs (k = 1000 kN/m) whose capacities
// differ by 1e-9. The first event opens one, the second is found a fraction
// of about 1e-9 of the rest of the step later, where a sub-step's velocities
// (displacements over its length) are round-off: it opens at the committed
// state instead, and the energy balance closes through both events.
TEST(HingeEvent, EventsARoundOffFractionApartCloseTheEnergyBalance) {
  for (const TimeIntegrator& ti :
       {TimeIntegrator::newmark(0.25, 0.5), TimeIntegrator::midPoint(0.1, 0.1)}) {
    Model m;
    m.resizeNodes(2);
    m.setCoord(0, Vec2(0, 0));
    m.setCoord(1, Vec2(1, 0));
    m.setElement(0, std::make_unique<JumpingCapacitySpring>(std::array{0, 1}, 1000.0, 10.0, 1e9));
    m.setElement(1, std::make_unique<JumpingCapacitySpring>(std::array{0, 1}, 1000.0,
                                                            10.0 * (1 + 1e-9), 1e9));
    m.bound(0) = {1, 1, 1};
    m.bound(1) = {0, 1, 1};
    m.nodalMass(1) = {1, 1, 0};
    m.force(1) = {100, 0, 0};
    Analysis an(m);
    an.setLoadFunction(1, ProportionalLoad::ramp());
    an.setIntegrator(ti);
    an.setDt(0.01);
    int opened = 0;
    an.onHingeActivated = [&](int, const HingeInfo&) { ++opened; };
    double largest = 0;
    for (int s = 1; s <= 30; ++s) {
      ASSERT_GT(solveStep(an), 0) << ti.describe() << " step " << s;
      ASSERT_TRUE(an.commit());
      const Energy e = an.energy();
      largest = std::max(largest, std::abs(e.balance()) / std::max(e.external, 1e-30));
    }
    EXPECT_EQ(opened, 2) << ti.describe();
    EXPECT_LT(largest, 1e-11) << ti.describe();
  }
}

}  // namespace
}  // namespace c2d
