// Ground friction (core/contact/GroundContact): the elastic-plastic Coulomb law (its
// work identity, bound and exact unsymmetric tangent), and a beam lying on the
// ground under gravity tilted by gx = 0.3 g: it sticks for mu = 0.5 (held by
// its springs, within mu N / k) and slides with acceleration (0.3 - mu) g for
// mu = 0.2, while total energy plus what friction took stays constant; the
// same for a heavy Lambda standing on two light nodes; a free member dropped
// flat on the ground rebounds with no more energy than it had.
#include <gtest/gtest.h>

#include <cmath>

#include "ContactTestSupport.h"
#include "core/contact/GroundContact.h"
#include "elements/Joints.h"
#include "solvers/TimeIntegrator.h"

namespace c2d {
namespace {

using test::addRod;
using test::kGravity;
using test::newRod;
using test::position;
using test::rod;
using test::solveStep;

TEST(GroundFriction, WorkIsTheSpringsChangePlusSlidingAndTheForceIsBounded) {
  const Ground g{0.0, 1e4, -1, 0.4};
  for (const StepRule& rule :
       {TimeIntegrator::midPoint(0, 0).rule(0.01), TimeIntegrator::statics().rule(1)}) {
    const ContactForce c = groundContact(g, 0.0, -1e-3, -1.2e-3, rule);
    ASSERT_GT(c.normal, 0);
    const double L = g.mu * c.normal / g.k;  // the spring's reach
    for (double a : {-2 * L, -0.5 * L, 0.0, 0.7 * L, 3 * L})
      for (double dx : {-0.3, -1.5 * L, -0.2 * L, -1e-9, 0.0, 3e-9, 0.4 * L, 2 * L, 0.2}) {
        const double xn = 0.0, x = xn + dx;
        const FrictionForce f = groundFriction(g, c, a, xn, x, rule);
        EXPECT_LE(std::abs(f.force), g.mu * c.normal * (1 + 1e-12));
        EXPECT_LE(std::abs(x - f.anchor), L * (1 + 1e-12));  // the spring within its reach
        EXPECT_GE(f.slipped, 0.0);
        if (rule.scheme != Scheme::MidPoint) continue;
        // The work against friction is the spring's change plus what sliding took.
        EXPECT_NEAR(-f.force * dx,
                    frictionEnergy(g, x - f.anchor) - frictionEnergy(g, xn - a) + f.slipped,
                    1e-12 * g.mu * c.normal * (L + std::abs(dx)))
            << "a " << a << " dx " << dx;
      }
    // Far along it slides at mu N against the motion; no friction off the ground.
    EXPECT_NEAR(groundFriction(g, c, 0.0, 0.0, 1.0, rule).force, -g.mu * c.normal,
                1e-3 * c.normal);
    const ContactForce free = groundContact(g, 0.0, 0.1, 0.05, rule);
    EXPECT_EQ(groundFriction(g, free, 0.0, 0.0, 0.1, rule).force, 0.0);
    EXPECT_EQ(groundFriction(g, free, 0.0, 0.0, 0.1, rule).anchor, 0.1);
  }
}

TEST(GroundFriction, AssembledTangentMatchesFiniteDifferences) {
  // A jointed two-link frame partly pressed into the ground, sliding on it.
  Model m;
  m.materials()[1] = rod(1, 2e3, 1e3, 30.0, 1.0, 0.01);
  const int b = addRod(m, m.addNode(Vec2(0, 0.02)), Vec2(1.0, -0.03), 2);
  const int c = m.addNode(m.coord(b));
  addRod(m, c, Vec2(1.8, 0.4), 2);
  m.joints().push_back({b, c, JointForm::Condensed});
  installJoints(m);
  m.ground() = Ground{0.0, 4.0e3, 0, 0.4};
  m.gravity() = Vec2(0.2 * kGravity, -kGravity);
  for (const TimeIntegrator& ti :
       {TimeIntegrator::statics(), TimeIntegrator::newmark(0.25, 0.5),
        TimeIntegrator::midPoint(0.1, 0.05), TimeIntegrator::midPoint(0, 0)}) {
    State s;
    s.resize(m.numNodes());
    s.dt = 0.05;
    test::scatteredState(s, 0.01, 0.006);
    // Springs that stick at some nodes and slide at others.
    for (int n = 0; n < m.numNodes(); ++n) s.stretch(n) = 0.004 * std::sin(3.1 * n);
    int inContact = 0;
    for (int n = 0; n < m.numNodes(); ++n)
      inContact += n != c && m.coord(n).y() + s.u(3 * n + 1) < 0;
    EXPECT_GE(inContact, 2);
    EXPECT_LT(test::tangentError(m, s, ti.rule(s.dt)), 1e-6) << ti.describe();
  }
}

// A stiff beam of mass 1 and length 1 (one element: equal nodal weights)
// lying on the ground y = 0, its nodes at their static penetration, gravity
// (0.3 g, -g).
struct Slide {
  double x = 0;             // displacement of the first node at the end
  double acceleration = 0;  // from its velocities at T/2 and T
  double largestStep = 0;   // largest |dx| of a step
  double reach = 0;         // mu N / k of an end node (its spring's reach)
  double worstBalance = 0;  // |E + dissipated - E0| over the run
  double dissipated = 0;
  bool converged = true;
};

// load > 0: instead a table, a beam 0.2 above the ground on two legs, with a
// mass `load` at its middle: two light feet carry it all.
Slide slide(double mu, double dt, int steps, double load = 0) {
  const int n = load > 0 ? 4 : 1;
  const double k = 1e5;
  Model m;
  m.materials()[1] = rod(1, 1e8, 1e8, 1e5, 1.0, 1e-4);
  if (load > 0) {
    m.materials()[2] = rod(2, 1e6, 1e6, 1e4, 1.0, 1e-4);
    const int foot = newRod(m, Vec2(0, 0), Vec2(0, 0.2), 1, 2);
    addRod(m, foot + 1, Vec2(1, 0.2), 2, 2);
    addRod(m, foot + 3, Vec2(1, 0), 1, 2);
    m.nodalMass(foot + 2) = {load, load, 0};
  } else {
    newRod(m, Vec2(0, 0), Vec2(1, 0), n);
  }
  m.ground() = Ground{0.0, k, 0, mu};
  m.gravity() = Vec2(0.3 * kGravity, -kGravity);
  Analysis an(m);
  // The table's frame rings on its stiff legs: damped by the scheme.
  an.setIntegrator(load > 0 ? TimeIntegrator::midPoint(0.2, 0.2) : TimeIntegrator::midPoint(0, 0));
  an.setTolerance(1e-24);
  an.setDt(dt);
  State& s = an.state();
  s.resize(m.numNodes());
  for (int i = 0; i <= n; ++i) {
    const double weight = load > 0 ? (i == 0 || i == n ? 0.5 * kGravity * (load + 1.4) : 0.0)
                                   : kGravity / n * (i == 0 || i == n ? 0.5 : 1.0);
    s.u(3 * i + 1) = s.un(3 * i + 1) = -weight / k;
  }
  Slide out;
  out.reach = mu * -s.u(1);
  double norm = 0;
  EXPECT_TRUE(an.formResidual(norm).ok);  // the elements' energy at the start
  const double e0 = an.energy().total();
  double b0 = 0;
  double vHalf = 0, xThird = 0, xTwoThirds = 0;
  const int watched = load > 0 ? 2 : 0;
  for (int i = 0; i < steps; ++i) {
    if (!solveStep(an)) {
      out.converged = false;
      return out;
    }
    const double d = an.assembler().contactDissipation(s, an.integrator().rule(dt));
    EXPECT_GE(d, 0.0);
    out.dissipated += d;
    for (int node = 0; node <= n; ++node)
      out.largestStep = std::max(out.largestStep, std::abs(s.u(3 * node) - s.un(3 * node)));
    an.commit();
    if (i == 0) b0 = an.energy().balance();
    // The table's scheme damps too: its account's balance.
    out.worstBalance = std::max(out.worstBalance, load > 0 ? std::abs(an.energy().balance() - b0)
                                                           : std::abs(an.energy().total() + out.dissipated - e0));
    if (i + 1 == steps / 2) vHalf = s.v(0);
    if (i + 1 == steps / 3) xThird = s.u(3 * watched);
    if (i + 1 == 2 * (steps / 3)) xTwoThirds = s.u(3 * watched);
  }
  out.x = s.u(3 * watched);
  // The table: from the loaded node's positions at T/3, 2T/3, T (its feet ring).
  const double third = dt * (steps / 3);
  out.acceleration = load > 0 ? (out.x - 2 * xTwoThirds + xThird) / (third * third)
                              : (s.v(0) - vHalf) / (dt * (steps - steps / 2));
  return out;
}

TEST(GroundFriction, BeamOnTheGroundStaysForMuAboveTheTilt) {
  // 0.3 g against mu g = 0.5 g: the springs hold the tangential load 0.6 mu N:
  // the beam moves by its springs' stretch, 0.6 of their reach, and no more
  // (no creep).
  const double dt = 1e-3;
  const Slide r = slide(0.5, dt, 500);
  ASSERT_TRUE(r.converged);
  EXPECT_LT(std::abs(r.x), 1.3 * 0.6 * r.reach);
  EXPECT_LT(r.worstBalance, 1e-9 * kGravity);
}

TEST(GroundFriction, BeamOnTheGroundSlidesWithTheTiltMinusMu) {
  // On a horizontal ground with gravity (0.3 g, -g) and friction mu = 0.2 the
  // beam slides with acceleration (0.3 - mu) g, x = 0.05 g t^2, after its
  // springs have stretched to their reach L, which takes t_s = sqrt(2 L /
  // (0.3 g)) with friction short of mu N: x leads by less than mu g t_s t.
  const double dt = 1e-3, t = 0.5;
  const Slide r = slide(0.2, dt, static_cast<int>(t / dt + 0.5));
  ASSERT_TRUE(r.converged);
  EXPECT_NEAR(r.acceleration, 0.1 * kGravity, 1e-5 * kGravity);
  const double ts = std::sqrt(2 * r.reach / (0.3 * kGravity));
  EXPECT_GT(r.x, 0.05 * kGravity * t * t);
  EXPECT_LT(r.x - 0.05 * kGravity * t * t, 0.2 * kGravity * ts * t);
  // Friction took mu W x; the balance closes with it.
  EXPECT_NEAR(r.dissipated, 0.2 * kGravity * r.x, 1e-3 * r.dissipated);
  EXPECT_LT(r.worstBalance, 1e-9 * kGravity);
}

// The same with the weight on two light nodes: friction resists with the
// full mu N whatever a node's own mass, so the table sticks and slides like
// the beam.
TEST(GroundFriction, HeavyTableOnTwoLightFeetStaysForMuAboveTheTilt) {
  const double dt = 1e-3;
  const Slide r = slide(0.5, dt, 500, 20.0);
  ASSERT_TRUE(r.converged);
  // Its springs' stretch and the feet's settling as the frame's ringing dies.
  EXPECT_LT(std::abs(r.x), 2 * r.reach);
  EXPECT_LT(r.worstBalance, 1e-9 * 21.4 * kGravity);
}

TEST(GroundFriction, HeavyTableOnTwoLightFeetSlidesWithTheTiltMinusMu) {
  const double dt = 1e-3, t = 0.5;
  const Slide r = slide(0.2, dt, static_cast<int>(t / dt + 0.5), 20.0);
  ASSERT_TRUE(r.converged);
  EXPECT_NEAR(r.acceleration, 0.1 * kGravity, 4e-3 * kGravity);
  EXPECT_LT(r.worstBalance, 1e-9 * 21.4 * kGravity);
}

// A tilted beam of four rods (its nodes first..first+4) just above a ground
// with a dashpot (zeta = 0.2) and friction (mu = 0.3), under gravity; returns
// its first node.
int tiltedBeam(Model& m) {
  m.materials()[1] = rod(1, 1e6, 1e6, 1e3, 1.0, 1e-4);
  const int first = newRod(m, Vec2(0, 0.05), Vec2(1, 0.15), 4);
  m.ground() = Ground{0.0, 2e4, 0.2, 0.3};
  m.gravity() = Vec2(0, -kGravity);
  return first;
}

// The tilted beam thrown down and sideways: every node at (1.5, -1) m/s.
void throwBeam(Analysis& an, int first) {
  State& s = an.state();
  s.resize(an.model().numNodes());
  for (int n = first; n < first + 5; ++n) s.v.segment<2>(3 * n) = Vec2(1.5, -1.0);
  s.vn = s.v;
}

TEST(GroundFriction, ImpactWithDissipationAndFrictionClosesTheEnergyBalance) {
  // A tilted beam thrown down and sideways onto the ground: the ground's
  // dashpot (zeta = 0.2) and friction (mu = 0.3) both take energy; total
  // energy plus contactDissipation stays constant.
  Model m;
  const int first = tiltedBeam(m);
  Analysis an(m);
  an.setIntegrator(TimeIntegrator::midPoint(0, 0));
  an.setTolerance(1e-24);
  const double dt = 2e-3;
  an.setDt(dt);
  an.impactSteps().setEnabled(false);  // every step of dt booked here
  throwBeam(an, first);
  State& s = an.state();
  const double e0 = an.energy().total();
  double dissipated = 0, worst = 0, friction = 0;
  for (int i = 0; i < 300; ++i) {
    ASSERT_TRUE(solveStep(an)) << "step " << i;
    const StepRule rule = an.integrator().rule(dt);
    const double d = an.assembler().contactDissipation(s, rule);
    EXPECT_GE(d, 0.0);
    // The ground's dashpot, 2 zeta sqrt(k m) per node; the rest is friction's.
    double damperPart = 0;
    for (int n = first; n < first + 5; ++n) {
      const double p0 = -(m.coord(n).y() + s.un(3 * n + 1)),
                   p1 = -(m.coord(n).y() + s.u(3 * n + 1));
      const double c = 2 * 0.2 * std::sqrt(2e4 * an.assembler().nodeMasses()[n]);
      damperPart += c * (std::max(p1, 0.0) - std::max(p0, 0.0)) * (p1 - p0) / dt;
    }
    friction += d - damperPart;
    dissipated += d;
    an.commit();
    worst = std::max(worst, std::abs(an.energy().total() + dissipated - e0));
  }
  const double scale = 0.5 * 3.25 + kGravity * 0.1;  // kinetic and potential at the start
  EXPECT_GT(friction, 0.05 * scale);
  EXPECT_GT(dissipated - friction, 1e-3 * scale);
  EXPECT_LT(worst, 1e-9 * scale);
}

TEST(GroundFriction, TheBalanceClosesWhenTheNextStepIsLongerThanTheOneCommitted) {
  // Step cutting lengthens dt again before the converged step is committed
  // (TIME commits): the friction booked at the commit must be the one the step
  // was solved with.
  Model m;
  const int first = tiltedBeam(m);
  Analysis an(m);
  an.setIntegrator(TimeIntegrator::midPoint(0.1, 0.1));
  an.setTolerance(1e-24);
  throwBeam(an, first);
  // The account starts at the first commit (the state set above is not booked).
  an.setDt(1e-3);
  ASSERT_TRUE(solveStep(an));
  ASSERT_TRUE(an.commit());
  const double b0 = an.energy().balance(), d0 = an.energy().dissipated;
  double worst = 0;
  an.onCommit = [&] { worst = std::max(worst, std::abs(an.energy().balance() - b0)); };
  for (int i = 0; i < 300; ++i) {
    an.setDt(i % 2 ? 2e-3 : 1e-3);  // advance() commits the step solved with the other length
    ASSERT_TRUE(solveStep(an)) << "step " << i;
  }
  an.setDt(4e-3);
  ASSERT_TRUE(an.commit());
  const double scale = 0.5 * 3.25 + kGravity * 0.1;  // kinetic and potential at the start
  EXPECT_GT(an.energy().dissipated - d0, 0.05 * scale);
  EXPECT_LT(worst, 1e-9 * scale);
}

TEST(GroundContactImpact, AFreeMemberDroppedFlatReboundsWithNoMoreEnergy) {
  // A free 1.5 m column element of the six-story frame falls flat at 10 m/s
  // onto the k = 1e5 ground: both ends hit in the same step of dt = 0.01 (the
  // contact period, 2 pi sqrt(m/k) = 2 pi sqrt(0.225 / 1e5) = 9.4 ms, is
  // shorter). The discrete gradient returns the kinetic energy exactly without
  // a dashpot and only takes energy with one; the account's balance closes.
  for (const double alpha : {0.0, 0.1}) {
    Model m;
    m.materials()[1] = rod(1, 3.6e6, 1.2e6, 48000, 0.3, 0.004);
    const int first = newRod(m, Vec2(0, 0.15), Vec2(1.5, 0.15), 1);
    m.ground() = Ground{0.0, 1e5, alpha, 0.0};
    Analysis an(m);
    an.setIntegrator(TimeIntegrator::midPoint(alpha, alpha));
    an.setDt(0.01);
    State& s = an.state();
    s.resize(m.numNodes());
    for (int n = first; n < first + 2; ++n) s.v.segment<2>(3 * n) = Vec2(0, -10);
    s.vn = s.v;
    const double before = 0.5 * 0.3 * 1.5 * 100;
    ASSERT_TRUE(solveStep(an));
    ASSERT_TRUE(an.commit());
    const double b0 = an.energy().balance();
    double worst = 0, deepest = 0;
    // At every commit (with the dashpot the impact is taken in shorter steps).
    an.onCommit = [&] {
      worst = std::max(worst, std::abs(an.energy().balance() - b0));
      for (int n = first; n < first + 2; ++n) deepest = std::max(deepest, -position(m, s, n).y());
    };
    for (int i = 0; i < 40; ++i) {
      ASSERT_TRUE(solveStep(an)) << "step " << i;
      ASSERT_TRUE(an.commit());
    }
    ASSERT_GT(deepest, 0.005);  // it struck the ground (15 mm at the peak)
    for (int n = first; n < first + 2; ++n) {
      EXPECT_GT(position(m, s, n).y(), 0.15);  // and left it again
      EXPECT_GT(s.v(3 * n + 1), 0);
    }
    const Energy after = an.energy();
    EXPECT_EQ(after.contact, 0.0);
    if (alpha == 0)
      EXPECT_NEAR(after.kinetic + after.strain, before, 1e-9 * before);
    else
      EXPECT_LT(after.kinetic + after.strain, 0.99 * before);
    EXPECT_LT(worst, 1e-9 * before);
  }
}

}  // namespace
}  // namespace c2d
