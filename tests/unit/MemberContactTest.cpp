// Member-to-member contact (core/contact/MemberContact): the assembled tangent
// and pattern, and whole analyses: bars colliding end-on and crosswise (energy
// and momentum), a bar dropped on a fixed beam (penetration, rebound,
// dissipation), a bar on a tilted beam (friction). The pair law:
// PairContactTest.cpp; the search: ContactSearchTest.cpp; step starts:
// PairStartsTest.cpp; the pairs' memory over commits: PairMemoriesTest.cpp; the
// crossing check: MemberCrossingTest.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include <vector>

#include "ContactTestSupport.h"
#include "core/contact/CrushingLaw.h"
#include "core/contact/MemberContact.h"
#include "core/contact/MemberCrossing.h"
#include "core/contact/SpringFriction.h"
#include "elements/Joints.h"
#include "solvers/ProportionalLoad.h"
#include "solvers/TimeIntegrator.h"
#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

using test::addRod;
using test::kGravity;
using test::newRod;
using test::position;
using test::rod;
using test::solveStep;

// --- pairs of a model ---------------------------------------------------------

TEST(MemberContactModel, AssembledTangentMatchesFiniteDifferences) {
  // A jointed two-link frame pressed onto a free bar, crossing it at an angle:
  // nodes of either pressed into segments of the other, on the static, Newmark
  // and mid-point rules.
  Model m;
  m.materials()[1] = rod(1, 2e3, 1e3, 30.0, 1.0, 1e-3);    // r = 0.055
  m.materials()[2] = rod(2, 4e3, 2e3, 50.0, 2.0, 1.5e-3);  // r = 0.047
  const int first = newRod(m, Vec2(-0.2, 0.09), Vec2(0.5, 0.02), 3);
  const int bend = m.numNodes() - 1;
  const int slave = m.addNode(m.coord(bend));
  addRod(m, slave, Vec2(1.2, 0.3), 2);
  m.joints().push_back({bend, slave, JointForm::Condensed});
  installJoints(m);
  // The bar lies 0.5 lower in the reference configuration (pairs within
  // contact distance there never contact) and is displaced into the frame.
  const int bar = newRod(m, Vec2(-0.3, -0.51), Vec2(1.1, -0.5), 4, 2);
  m.memberContact() = MemberContactData{5e3, 0, -1};
  (void)first;
  for (const TimeIntegrator& ti :
       {TimeIntegrator::statics(), TimeIntegrator::newmark(0.25, 0.5),
        TimeIntegrator::midPoint(0.1, 0.05), TimeIntegrator::midPoint(0, 0)}) {
    State s;
    s.resize(m.numNodes());
    test::scatteredState(s, 0.004, 0.006);
    for (int n = bar; n < bar + 5; ++n) {
      s.un(3 * n + 1) += 0.5;
      s.u(3 * n + 1) += 0.5;
    }
    Assembler as(m);
    as.refresh();
    int active = 0;
    PairVec f;
    PairMat k;
    MemberContact& mc = *as.memberContact();
    const MemberContact::Nearby nearby = mc.nearby(m, s, mc.slack());
    for (std::size_t i = 0; i < nearby.candidates.size(); ++i)
      active += mc.evaluate(static_cast<int>(i), m, s, ti.rule(0.05), false, f, k);
    EXPECT_GE(active, 4) << ti.describe();
    EXPECT_LT(test::tangentError(m, s, ti.rule(0.05)), 1e-6) << ti.describe();
  }
}

TEST(MemberContactModel, ThePatternHoldsThePairsAboutToTouchOnly) {
  // A bar pressed with one end onto a diagonal rod, its other end inside the
  // box of the rod's segment but 0.21 from its line (contact distance 0.1,
  // the pattern's reserve a quarter of the search margin, 0.06): the pattern
  // couples the pressed node with the segment's ends and not the far one,
  // whose coupling would only add fill to the factors (the boxes of members
  // lying at an angle across each other overlap far beyond touching).
  Model m;
  m.materials()[1] = rod(1, 1e4, 1e4, 10, 1.0, 2.5e-3 / 3);  // r = 0.05
  newRod(m, Vec2(0, 0), Vec2(1, 1), 2);
  // 0.5 lower in the reference configuration (pairs within contact distance
  // there never contact), displaced up into place.
  const int bar = newRod(m, Vec2(0.1, -0.1), Vec2(0.25, -0.2), 1);
  const int pressed = bar + 1;
  m.memberContact() = MemberContactData{1e3, 0, -1};
  Assembler as(m);
  as.refresh();
  State s;
  s.resize(m.numNodes());
  for (int n = bar; n <= pressed; ++n) s.u(3 * n + 1) = s.un(3 * n + 1) = 0.5;
  const StepRule rule = TimeIntegrator::statics().rule(0);
  const Eigen::VectorXd factors = Eigen::VectorXd::Zero(3 * m.numNodes());
  ASSERT_TRUE(as.assemble(s, rule, factors, true));  // the pattern without pairs
  ASSERT_TRUE(as.assemble(s, rule, factors, true));  // and with the pressed pair
  const SparseMatrix& K = as.tangent();
  auto coupled = [&](int a, int b) {
    const int i = as.dofs().eq(a, 0), j = as.dofs().eq(b, 0);
    for (SparseMatrix::InnerIterator it(K, j); it; ++it)
      if (it.row() == i) return true;
    return false;
  };
  const int segmentEnd = 1;  // the diagonal's middle node: end b of its first segment
  ASSERT_TRUE(coupled(pressed, 0));
  EXPECT_TRUE(coupled(pressed, segmentEnd));
  EXPECT_FALSE(coupled(bar, 0));
  EXPECT_FALSE(coupled(bar, segmentEnd));
}

// --- collisions ---------------------------------------------------------------

struct Collision {
  double worstEnergy = 0;    // largest |E - E0| / E0 over the steps
  double worstMomentum = 0;  // largest |p - p0| / |p0|
  double peakContact = 0;    // largest contact energy / E0: the impact happened
  bool converged = true;
};

Collision collide(Model& m, Analysis& an, int steps) {
  State& s = an.state();
  const double e0 = an.energy().total();
  const Vec2 p0 = test::linearMomentum(m, s);
  Collision out;
  for (int i = 0; i < steps; ++i) {
    if (!solveStep(an)) {
      out.converged = false;
      break;
    }
    an.commit();
    const Energy e = an.energy();
    out.worstEnergy = std::max(out.worstEnergy, std::abs(e.total() - e0) / e0);
    out.worstMomentum =
        std::max(out.worstMomentum, (test::linearMomentum(m, s) - p0).norm() / p0.norm());
    out.peakContact = std::max(out.peakContact, e.contact / e0);
  }
  return out;
}

void setVelocity(const Model& m, State& s, int firstNode, int lastNode, const Vec2& v) {
  s.resize(m.numNodes());
  for (int n = firstNode; n <= lastNode; ++n) s.v.segment<2>(3 * n) = v;
  s.vn = s.v;
}

TEST(MemberContactCollision, BarsEndOnConserveEnergyAndMomentum) {
  Model m;
  m.materials()[1] = rod(1, 1e4, 1e4, 50.0, 1.0, 1e-4);  // r = 0.0173
  newRod(m, Vec2(-1.05, 0), Vec2(-0.05, 0), 4);
  const int second = newRod(m, Vec2(0.05, 0), Vec2(1.05, 0), 4);
  m.memberContact() = MemberContactData{2e3, 0, -1};
  Analysis an(m);
  an.setIntegrator(TimeIntegrator::midPoint(0, 0));
  an.setTolerance(1e-24);
  an.setDt(2e-3);
  setVelocity(m, an.state(), 0, second - 1, Vec2(1.0, 0));
  const Collision c = collide(m, an, 250);
  ASSERT_TRUE(c.converged);
  EXPECT_GT(c.peakContact, 0.1);
  EXPECT_LT(c.worstEnergy, 1e-10);
  EXPECT_LT(c.worstMomentum, 1e-11);
  // After the impact the second bar moves on, faster than the first.
  const State& s = an.state();
  EXPECT_GT(s.v(3 * (second + 2)), 0.5);
  EXPECT_LT(s.v(3 * 2), 0.5);
  EXPECT_TRUE(findCrossings(m, s).empty());
}

TEST(MemberContactCollision, BarsCrosswiseConserveEnergyAndMomentum) {
  // A vertical bar falls (no gravity: thrown) on the interior of a free
  // horizontal one, off its centre: both turn after the impact.
  Model m;
  m.materials()[1] = rod(1, 1e4, 1e4, 50.0, 1.0, 1e-4);
  const int lying = newRod(m, Vec2(-0.5, 0), Vec2(0.5, 0), 4);
  const int standing = newRod(m, Vec2(0.13, 0.08), Vec2(0.13, 1.08), 4);
  m.memberContact() = MemberContactData{2e3, 0, -1};
  Analysis an(m);
  an.setIntegrator(TimeIntegrator::midPoint(0, 0));
  an.setTolerance(1e-24);
  an.setDt(2e-3);
  setVelocity(m, an.state(), standing, standing + 4, Vec2(0, -1.0));
  const Collision c = collide(m, an, 200);
  ASSERT_TRUE(c.converged);
  EXPECT_GT(c.peakContact, 0.1);
  EXPECT_LT(c.worstEnergy, 1e-10);
  EXPECT_LT(c.worstMomentum, 1e-11);
  const State& s = an.state();
  double lyingVy = 0;
  for (int n = lying; n < lying + 5; ++n) lyingVy += s.v(3 * n + 1) / 5;
  EXPECT_LT(lyingVy, -0.1);                // the lying bar was pushed down
  EXPECT_GT(s.v(3 * standing + 1), -0.9);  // and slowed the standing one
  EXPECT_TRUE(findCrossings(m, s).empty());
}

// --- a bar on a fixed beam ----------------------------------------------------

// A fixed beam (0, 0)-(4, 0) of two elements and a stiff bar of one element
// and mass 1 from x = 0.6 to 1.4 at height y0: the bar's two nodes meet the
// interior of the beam's first element (the beam's nodes are beyond the bar's
// ends): two pairs, each with stiffness k.
struct BarOnBeam {
  Model m;
  int bar = -1;
  double h = 0;  // contact distance
};

BarOnBeam barOnBeam(double y0, double k, double zeta, double mu = 0, double e = 1) {
  BarOnBeam b;
  b.m.materials()[1] = rod(1, 1e7, 1e7, 1e5, 1.25, 1e-3);  // bar: mass 1.25 * 0.8 = 1, r = 0.049
  b.m.materials()[2] = rod(2, 1e6, 1e6, 1e3, 0.5, 1e-3);   // beam: r = 0.077
  const int beam = newRod(b.m, Vec2(0, 0), Vec2(4, 0), 2, 2);
  for (int n = beam; n < beam + 3; ++n) b.m.bound(n) = {1, 1, 1};
  b.bar = newRod(b.m, Vec2(0.6, y0), Vec2(1.4, y0), 1, 1);
  b.m.gravity() = Vec2(0, -kGravity);
  b.m.memberContact() = MemberContactData{k, zeta, -1, e, mu};
  b.h = std::sqrt(3e-3 / 1.25) + std::sqrt(3e-3 / 0.5);
  return b;
}

TEST(MemberContactBarOnBeam, StaticPenetrationIsWeightOverPairsTimesK) {
  const double k = 4e4, weight = kGravity;
  // Above the contact distance in the reference configuration (pairs closer
  // than that never contact), started inside it so that the first tangent has
  // contact stiffness.
  BarOnBeam b = barOnBeam(0.2, k, 0);
  b.m.bound(b.bar)[0] = 1;  // frictionless: hold the bar's horizontal rigid motion
  Analysis an(b.m);
  State& s = an.state();
  s.resize(b.m.numNodes());
  for (int n : {b.bar, b.bar + 1}) s.u(3 * n + 1) = s.un(3 * n + 1) = b.h - 0.2 - 1e-4;
  an.setDt(1.0);
  ASSERT_TRUE(solveStep(an));
  an.commit();
  for (int n : {b.bar, b.bar + 1}) {
    const double penetration = b.h - position(b.m, s, n).y();
    EXPECT_NEAR(penetration, weight / (2 * k), 1e-9 * weight / k);
  }
  EXPECT_NEAR(an.energy().contact, 2 * 0.5 * k * std::pow(weight / (2 * k), 2),
              1e-9 * weight * weight / k);
}

struct Drop {
  double rebound = 0;      // highest point of the bar's first node after the first impact
  double firstImpact = 0;  // what the contact took until the bar left it the first time
  double deepest = 0;     // largest penetration of the bar's first node at a commit
  double dissipated = 0;  // sum of contactDissipation over the steps
  double worstBalance = 0;
  double energyScale = 0;
  bool converged = true;
};

Drop dropBar(double zeta, double dt, int steps, double e = 1) {
  // Dropped from 0.05 above contact.
  const double k = 2e4;
  BarOnBeam b = barOnBeam(0, k, zeta, 0, e);
  for (int n = 0; n < b.m.numNodes(); ++n)
    if (n >= b.bar) b.m.setCoord(n, b.m.coord(n) + Vec2(0, b.h + 0.05));
  Analysis an(b.m);
  an.setIntegrator(TimeIntegrator::midPoint(0, 0));
  an.setTolerance(1e-24);
  an.setDt(dt);
  State& s = an.state();
  Drop out;
  out.energyScale = kGravity * 0.05;
  double e0 = an.energy().total();
  bool touched = false, left = false, landed = false;
  // The steps keep their length (no impact steps): each is booked here.
  an.impactSteps().setEnabled(false);
  for (int i = 0; i < steps; ++i) {
    if (!solveStep(an)) {
      out.converged = false;
      break;
    }
    const double d = an.assembler().contactDissipation(s, an.integrator().rule(dt));
    EXPECT_GE(d, 0.0);
    const double before = an.energy().dissipated;
    an.commit();
    // What the commit took (an impact's peak: core/contact/CrushingLaw.h).
    const double released = an.energy().dissipated - before - d;
    out.dissipated += d + (e < 1 ? released : 0.0);
    const Energy e = an.energy();
    out.worstBalance = std::max(out.worstBalance, std::abs(e.total() + out.dissipated - e0));
    if (e.contact > 0) {
      touched = true;
      landed = left;
    }
    out.deepest = std::max(out.deepest, b.h - position(b.m, s, b.bar).y());
    if (touched && e.contact == 0 && !landed) {
      if (!left) out.firstImpact = out.dissipated;
      left = true;
      out.rebound = std::max(out.rebound, position(b.m, s, b.bar).y() - b.h);
    }
  }
  EXPECT_TRUE(touched);
  return out;
}

TEST(MemberContactBarOnBeam, ConservingDropReboundsToTheDropHeight) {
  const Drop d = dropBar(0, 1e-3, 260);
  ASSERT_TRUE(d.converged);
  EXPECT_EQ(d.dissipated, 0.0);
  EXPECT_LT(d.worstBalance, 1e-10 * d.energyScale);
  // Free flight is exact for the mid-point rule: the highest sample lies within
  // g dt^2 of the apex.
  EXPECT_NEAR(d.rebound, 0.05, kGravity * 1e-6 + 1e-9);
}

TEST(MemberContactBarOnBeam, DissipationLowersTheReboundAndClosesTheBalance) {
  const Drop d = dropBar(0.3, 1e-3, 260);
  ASSERT_TRUE(d.converged);
  EXPECT_GT(d.firstImpact, 0.01 * d.energyScale);
  EXPECT_LT(d.worstBalance, 1e-10 * d.energyScale);
  EXPECT_LT(d.rebound, 0.05 - d.firstImpact / kGravity + kGravity * 1e-6);
}

TEST(MemberContactBarOnBeam, CrushingImpactReboundsToTheRestitutionsHeight) {
  // Restitution e: the bar leaves the set q (1 - e^2) of its deepest
  // penetration q with e times its speed there, so its apex above the contact
  // distance is e^2 h0 - q (1 - e^2) (as the ground's, decks/collapse/bar_bounce);
  // the energy it lost is the crushing's, and the balance closes.
  const double e = 0.5, h0 = 0.05;
  const Drop d = dropBar(0, 1e-3, 260, e);
  ASSERT_TRUE(d.converged);
  EXPECT_GT(d.deepest, 0.0);
  EXPECT_NEAR(d.rebound, e * e * h0 - d.deepest * (1 - e * e), 3 * kGravity * 1e-6);
  // The first impact took at least the height lost (the bar lands again).
  EXPECT_GT(d.dissipated, kGravity * (h0 - d.rebound) - 1e-9);
  EXPECT_LT(d.worstBalance, 1e-10 * d.energyScale);
}

// A bar resting on the beam under gravity tilted by gx = 0.3 g (started at its
// static penetration): with mu = 0.5 it stays within the friction springs'
// reach (a bar of mass 1, two pairs); with mu = 0.2 it slides as x = (0.3 - 0.2) g t^2 / 2 after the
// springs' stretch mu N / k.
double slideOnBeam(double mu, double time) {
  const double k = 4e4;
  BarOnBeam b = barOnBeam(0.2, k, 0, mu);
  b.m.gravity() = Vec2(0.3 * kGravity, -kGravity);
  Analysis an(b.m);
  an.setIntegrator(TimeIntegrator::midPoint(0, 0));
  an.setTolerance(1e-20);
  const double dt = 1e-3;
  an.setDt(dt);
  State& s = an.state();
  s.resize(b.m.numNodes());
  for (int n : {b.bar, b.bar + 1})
    s.u(3 * n + 1) = s.un(3 * n + 1) = b.h - 0.2 - kGravity / (2 * k);
  const double x0 = position(b.m, s, b.bar).x();
  double e0 = an.energy().total(), dissipated = 0, worst = 0;
  for (int i = 0; i < static_cast<int>(time / dt + 0.5); ++i) {
    EXPECT_TRUE(solveStep(an));
    dissipated += an.assembler().contactDissipation(s, an.integrator().rule(dt));
    an.commit();
    const Energy en = an.energy();
    worst = std::max(worst, std::abs(en.total() + dissipated - e0));
  }
  EXPECT_LT(worst, 1e-9) << "mu " << mu;
  EXPECT_TRUE(findCrossings(b.m, s).empty());
  return position(b.m, s, b.bar).x() - x0;
}

TEST(MemberContactFriction, BarOnTiltedBeamStaysOrSlides) {
  const double k = 4e4, t = 0.3;
  const double stays = slideOnBeam(0.5, t);
  // Sticking: within twice the springs' static stretch 0.3 g m / (2 k) (the
  // overshoot of the tilt applied at once).
  EXPECT_LT(std::abs(stays), 2 * 0.3 * kGravity / 2 / k);
  // Sliding: the closed form to 5 % (the start, where the springs stretch at
  // 0.3 g for 4 ms before the bar slides, leaves it 0.005 m/s ahead).
  const double slides = slideOnBeam(0.2, t);
  EXPECT_NEAR(slides, 0.05 * kGravity * t * t, 0.05 * 0.05 * kGravity * t * t);
  EXPECT_GT(slides, 0.05 * kGravity * t * t);
}

TEST(MemberContactDeck, ZeroStiffnessSwitchesMemberContactOff) {
  // decks/collapse/bar_on_beam.inp with MEMBers,,0 (and values a study keeps
  // for when it turns the contact on): the echo says the contact is off and
  // its other values unused, and the bar falls through the beam as if free
  // (g t^2 / 2 after 0.24 s), where with contact it rebounds.
  std::string deck =
      testing::readText(std::string(C2D_SOURCE_DIR) + "/decks/collapse/bar_on_beam.inp");
  const std::string on = "  MEMBers,,k\n";
  const auto at = deck.find(on);
  ASSERT_NE(at, std::string::npos);
  deck.replace(at, on.size(), "  MEMBers,,0,,,0.3,0.5\n");
  testing::DeckTempDir dir;
  const testing::DeckResult r = testing::runDeckText(dir, "off.inp", deck);
  ASSERT_EQ(r.outcome.exitCode, 0) << r.outcome.message;
  EXPECT_NE(r.log.find("off (k = 0: the record's other values are not used)"), std::string::npos);
  const std::vector<double> y = testing::readCsv(r.out / "off_tplot.csv").column("disp_4_2");
  ASSERT_FALSE(y.empty());
  EXPECT_NEAR(y.back(), -0.5 * kGravity * 0.24 * 0.24, 1e-9);
}

}  // namespace
}  // namespace c2d
