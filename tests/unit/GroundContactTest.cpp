// The ground contact of verification.md V6 (core/contact/GroundContact): the
// mid-point force is the discrete gradient of the penalty's energy and the
// dashpot's force is continuous and dissipates; the static penetration is the
// weight over the nodes' stiffness; a dropped bar matches the rigid drop's
// contact time, penetration and rebound, and the dashpot lowers the rebound by
// the energy it dissipates, the same at every step; the assembled tangent with
// contact against finite differences. With restitution e < 1 the crushing law's
// mid-point force does the law's work over the step (what is stored plus what
// crushing dissipates), its tangent is the derivative of the force, the law
// reduces to the elastic one as e -> 1, and the loading point follows the
// largest penetration and is forgotten off the ground.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/Assembler.h"
#include "core/contact/GroundContact.h"
#include "core/Model.h"
#include "elements/Joints.h"
#include "solvers/Analysis.h"
#include "solvers/TimeIntegrator.h"
#include "tests/unit/ContactTestSupport.h"

namespace c2d {
namespace {

using test::addRod;
using test::position;
using test::rod;
using test::solveStep;
using test::totalMass;
using test::zeroCrossings;

constexpr double kPi = std::numbers::pi;
constexpr double kG = test::kGravity;

TEST(GroundContact, MidPointForceIsTheDiscreteGradient) {
  Ground g{0.5, 3.0e3, -1};
  StepRule rule;
  rule.scheme = Scheme::MidPoint;
  const double ys[] = {0.7, 0.5, 0.49, 0.3, 0.2999999, 0.51, -0.1};
  for (double y0 : ys)
    for (double y1 : ys) {
      if (y0 == y1) continue;
      const ContactForce c = groundContact(g, 0.0, y0, y1, rule);
      // Work of the upward force over the step = -(U1 - U0).
      const double work = c.force * (y1 - y0);
      EXPECT_NEAR(work, -(contactEnergy(g, 0.0, y1) - contactEnergy(g, 0.0, y0)), 1e-12 * g.k)
          << y0 << " -> " << y1;
      // Tangent: d force / d penetration(y1) = -d force / d y1.
      const double h = 1e-7;
      const double fd =
          -(groundContact(g, 0.0, y0, y1 + h, rule).force - groundContact(g, 0.0, y0, y1 - h, rule).force) /
          (2 * h);
      if (std::abs(y1 - g.y0) > 1e-6) {
        EXPECT_NEAR(c.tangent, fd, 1e-5 * g.k) << y0 << " " << y1;
      }
    }
  // The dashpot: c (<p1> - <p0>) / h on top while in contact (core/contact/ContactDamper.h).
  rule.h = 0.01;
  const GroundDamper d{600.0};
  const ContactForce c0 = groundContact(g, 0.0, 0.45, 0.40, rule),
                     c1 = groundContact(g, 0.0, 0.45, 0.40, rule, d);
  EXPECT_NEAR(c1.force - c0.force, 600.0 * 0.05 / rule.h, 1e-12 * g.k);
  // Entering or leaving, the dashpot's force is continuous where the node
  // passes the ground line (a jump there makes Newton's method cycle), never
  // does work on the node, and its tangent is the derivative of the force.
  for (double yn : {0.7, 0.52, 0.45, 0.3}) {
    const double eps = 1e-9;
    const ContactForce above = groundContact(g, 0.0, yn, g.y0 + eps, rule, d),
                       below = groundContact(g, 0.0, yn, g.y0 - eps, rule, d);
    EXPECT_NEAR(above.force, below.force, 10 * (g.k + d.c / rule.h) * eps) << "from y = " << yn;
    for (double y1 : {0.8, 0.51, 0.49, 0.35}) {
      const double diss =
          groundContact(g, 0.0, yn, y1, rule, d).force - groundContact(g, 0.0, yn, y1, rule).force;
      EXPECT_LE(diss * (y1 - yn), 0.0) << yn << " -> " << y1;
      const double h = 1e-7;
      const double fd = -(groundContact(g, 0.0, yn, y1 + h, rule, d).force -
                          groundContact(g, 0.0, yn, y1 - h, rule, d).force) /
                        (2 * h);
      EXPECT_NEAR(groundContact(g, 0.0, yn, y1, rule, d).tangent, fd, 1e-5 * g.k)
          << yn << " -> " << y1;
    }
  }
}

// A bar of n elements lying flat at height y, stiff and uniform, mass 1.
Model bar(int n, double y, const Ground& ground, double ei = 1e5) {
  Model m;
  m.materials()[1] = rod(1, 1e3 * ei, 1e3 * ei, ei, 1.0, 1e-4);
  const int first = m.addNode(Vec2(0, y));
  addRod(m, first, Vec2(1.0, y), n);
  m.gravity() = Vec2(0, -kG);
  m.ground() = ground;
  return m;
}

TEST(GroundContact, StaticPenetrationIsWeightOverNodesTimesK) {
  const double k = 2.0e4, weight = 1.0 * kG;
  for (int n : {1, 4}) {
    // Start slightly inside the ground so that the first tangent has contact stiffness.
    // Equal springs but unequal consistent nodal weights: a very stiff bar, so
    // that the rigid-bar answer holds node by node (k l^3/EI = 2e-5).
    Model m = bar(n, 0.0, Ground{1e-5, k, 0}, 1e9);
    m.bound(0)[0] = 1;  // frictionless: fix the horizontal rigid motion
    Analysis an(m);
    an.setDt(1.0);
    ASSERT_TRUE(solveStep(an));
    an.commit();
    double mean = 0;
    const int nodes = n + 1;
    for (int i = 0; i < nodes; ++i)
      mean += penetration(*m.ground(), position(m, an.state(), i).y());
    mean /= nodes;
    EXPECT_NEAR(mean, weight / (nodes * k), 1e-12 * weight / k) << n << " elements";
    for (int i = 0; i < nodes; ++i)
      EXPECT_NEAR(penetration(*m.ground(), position(m, an.state(), i).y()), weight / (nodes * k),
                  1e-5 * weight / (nodes * k));
  }
}

struct DropResult {
  double contactTime = 0, maxPenetration = 0, reboundHeight = 0, startHeight = 0;
  bool energyNeverIncreased = true;
  // Largest change of total + dissipated energy over the commits, and the
  // total dissipated energy (the account's).
  double worstIdentity = 0, dissipated = 0, energyScale = 0;
};

// One element bar (equal nodal masses and loads: a rigid translation) thrown
// down from height y0 with speed v0 onto the ground y = 0 whose dashpot has
// the damping ratio zeta.
DropResult drop(double zeta, double k, double y0, double v0, double dt) {
  Model m = bar(1, y0, Ground{0.0, k, zeta});
  Analysis an(m);
  an.setIntegrator(TimeIntegrator::midPoint(0, 0));
  an.setDt(dt);
  State& s = an.state();
  s.resize(m.numNodes());
  s.v(1) = s.v(4) = -v0;
  s.vn = s.v;
  DropResult out;
  out.startHeight = y0 + v0 * v0 / (2 * kG);
  std::vector<double> t{0}, p{-y0};
  out.energyScale = totalMass(m) * kG * out.startHeight;
  double before = an.energy().total();
  // Every commit (the steps through the impact are shortened: solvers/ImpactSteps.h);
  // the account starts at the first.
  bool first = true;
  double balance0 = 0, dissipated0 = 0;
  an.onCommit = [&] {
    const Energy e = an.energy();
    if (first) {
      balance0 = e.balance();
      dissipated0 = e.dissipated;
      first = false;
    }
    if (e.total() > before + 1e-12 * out.energyScale) out.energyNeverIncreased = false;
    out.worstIdentity = std::max(out.worstIdentity, std::abs(e.balance() - balance0));
    out.dissipated = e.dissipated - dissipated0;
    before = e.total();
    t.push_back(s.tn);
    p.push_back(-(m.coord(0).y() + s.un(1)));
    EXPECT_NEAR(s.un(4), s.un(1), 1e-12);
  };
  bool left = false;
  for (int i = 0; i < 20000 && !left; ++i) {
    EXPECT_TRUE(solveStep(an)) << "step " << i;
    an.commit();
    // Out of contact and rising for a few steps: done.
    left = p.size() > 5 && p.back() < 0 && p[p.size() - 2] < 0 && p[p.size() - 4] > 0;
  }
  EXPECT_TRUE(left);
  // Contact from the first to the second crossing of penetration zero.
  const auto c = zeroCrossings(t, p);
  EXPECT_EQ(c.size(), 2u);
  if (c.size() >= 2) out.contactTime = c[1] - c[0];
  // Maximum penetration from a parabola through the largest sample and its neighbours.
  const size_t i = std::max_element(p.begin(), p.end()) - p.begin();
  const double a = p[i - 1], b = p[i], cc = p[i + 1];
  out.maxPenetration = b + (a - cc) * (a - cc) / (8 * (2 * b - a - cc));
  // Free flight after the impact is exact for the mid-point rule: y + v^2/(2g).
  const double y = position(m, s, 0).y(), v = s.v(1);
  out.reboundHeight = y + v * v / (2 * kG);
  return out;
}

TEST(GroundContact, DroppedBarMatchesTheRigidDropFormulas) {
  const double mass = 1.0, k = 5.0e3, y0 = 0.01, vStart = 2.0;
  const double kTotal = 2 * k;                                 // two nodes
  const double v0 = std::sqrt(vStart * vStart + 2 * kG * y0);  // at first contact
  const double omega = std::sqrt(kTotal / mass);
  const double tc = (kPi + 2 * std::atan(kG / (omega * v0))) / omega;
  const double dt = tc / 500;
  const DropResult r = drop(0, k, y0, vStart, dt);
  const double st = mass * kG / kTotal;
  const double pMax = st + std::sqrt(st * st + mass * v0 * v0 / kTotal);
  EXPECT_NEAR(r.contactTime / tc, 1.0, 2e-5) << r.contactTime << " vs " << tc;
  EXPECT_NEAR(r.maxPenetration / pMax, 1.0, 1e-6) << r.maxPenetration << " vs " << pMax;
  EXPECT_NEAR(r.reboundHeight / r.startHeight, 1.0, 1e-10);
  EXPECT_TRUE(r.energyNeverIncreased);
  EXPECT_LT(r.worstIdentity, 1e-12 * r.energyScale);
}

TEST(GroundContact, ContactDampingLowersTheReboundTheSameAtEveryStep) {
  // The dashpot c = 2 zeta sqrt(k m) of each node's mass m takes
  // c (<p_n+1> - <p_n>)(p_n+1 - p_n) / h per step and node: the same damper at
  // every step, so the rebound converges as the step shrinks (the former
  // alpha k (<p_n+1> - <p_n>) was a damper alpha k h that vanished with it).
  const double k = 5.0e3, y0 = 0.01, vStart = 2.0, zeta = 0.1;
  double rebound[2] = {0, 0};
  int i = 0;
  for (double dt : {3.3e-2 / 300, 3.3e-2 / 20}) {
    const DropResult elastic = drop(0, k, y0, vStart, dt);
    const DropResult damped = drop(zeta, k, y0, vStart, dt);
    EXPECT_NEAR(elastic.reboundHeight / elastic.startHeight, 1.0, 1e-10);
    EXPECT_TRUE(damped.energyNeverIncreased);
    EXPECT_LT(damped.worstIdentity, 1e-12 * damped.energyScale);
    // The rebound height is lowered by exactly the dissipated energy.
    EXPECT_NEAR(damped.startHeight - damped.reboundHeight, damped.dissipated / kG,
                1e-10 * damped.startHeight);
    EXPECT_GT(damped.dissipated, 1e-2 * damped.energyScale) << "dt " << dt;
    rebound[i++] = damped.reboundHeight;
  }
  EXPECT_NEAR(rebound[1] / rebound[0], 1.0, 0.02);
}

TEST(GroundContact, AssembledTangentWithContactMatchesFiniteDifferences) {
  // A jointed two-link frame partly pressed into the ground.
  Model m;
  m.materials()[1] = rod(1, 2e3, 1e3, 30.0, 1.0, 0.01);
  const int a = m.addNode(Vec2(0, 0.02));
  const int b = addRod(m, a, Vec2(1.0, -0.03), 2);
  const Vec2 xb = m.coord(b);
  const int c = m.addNode(xb);
  addRod(m, c, Vec2(1.8, 0.4), 2);
  m.joints().push_back({b, c, JointForm::Condensed});
  installJoints(m);
  m.ground() = Ground{0.0, 4.0e3, 0};
  m.gravity() = Vec2(0, -kG);
  for (const TimeIntegrator& ti :
       {TimeIntegrator::statics(), TimeIntegrator::newmark(0.25, 0.5),
        TimeIntegrator::midPoint(0.1, 0.05), TimeIntegrator::midPoint(0, 0)}) {
    Assembler as(m);
    as.refresh();
    State s;
    s.resize(m.numNodes());
    test::scatteredState(s, 0.01, 0.02);
    const StepRule rule = ti.rule(0.05);
    const Eigen::VectorXd ones = Eigen::VectorXd::Ones(s.u.size());
    ASSERT_TRUE(as.assemble(s, rule, ones, true).ok);
    const Eigen::MatrixXd k = Eigen::MatrixXd(as.tangent());
    const DofMap& dofs = as.dofs();
    const int neq = dofs.numEquations();
    Eigen::VectorXd r0;
    as.toEquations(as.nodalResidual(), r0);
    // Penetrating nodes exist and none sits on the ground line.
    int inContact = 0;
    for (int n = 0; n < m.numNodes(); ++n) {
      if (!dofs.used(n)) continue;
      const double p = -(m.coord(n).y() + s.u(3 * n + 1));
      ASSERT_GT(std::abs(p), 1e-4);
      inContact += p > 0;
    }
    EXPECT_GE(inContact, 2);
    Eigen::MatrixXd fd(neq, neq);
    const double h = 1e-7;
    for (int n = 0; n < m.numNodes(); ++n)
      for (int d = 0; d < 3; ++d) {
        const int eq = dofs.eq(n, d);
        if (eq < 0) continue;
        Eigen::VectorXd rp, rm;
        s.u(3 * n + d) += h;
        ASSERT_TRUE(as.assemble(s, rule, ones, false).ok);
        as.toEquations(as.nodalResidual(), rp);
        s.u(3 * n + d) -= 2 * h;
        ASSERT_TRUE(as.assemble(s, rule, ones, false).ok);
        as.toEquations(as.nodalResidual(), rm);
        s.u(3 * n + d) += h;
        fd.col(eq) = (rp - rm) / (2 * h);
      }
    EXPECT_LT((fd - k).cwiseAbs().maxCoeff(), 1e-6 * k.cwiseAbs().maxCoeff()) << ti.describe();
  }
}

// --- with restitution e < 1: the crushing law ---------------------------------

struct Case {
  double q, p0, p1;  // loading point, penetrations at t_n and t_n+1
};

// Steps that stay on one branch, cross the set, the loading point, both, enter
// and leave the ground, in both directions, and hardly move.
std::vector<Case> cases(double q) {
  std::vector<Case> out;
  const double set = q * (1 - 0.25), pts[] = {-0.4 * q, 0.2 * q, 0.8 * q, 0.95 * q, q, 1.3 * q};
  for (double a : pts)
    for (double b : pts)
      if (a <= q) out.push_back({q, a, b});
  out.push_back({q, set - 1e-9, set + 1e-9});
  out.push_back({q, q - 1e-9, q + 1e-9});
  out.push_back({q, 0.9 * q, 0.9 * q + 1e-12});
  return out;
}

TEST(GroundCrushing, MidPointForceDoesTheWorkStoredPlusDissipated) {
  const Ground g{0.0, 1e4, 0.0, 0.0, 0.5};
  const StepRule rule = TimeIntegrator::midPoint(0, 0).rule(0.01);
  for (const Case& c : cases(2e-3)) {
    const double y0 = -c.p0, y1 = -c.p1;
    const ContactForce f = groundContact(g, c.q, y0, y1, rule);
    // The force acts upward: its work on the penetration's increment.
    const double work = f.force * (c.p1 - c.p0);
    const double stored = contactEnergy(g, c.q, y1) - contactEnergy(g, c.q, y0);
    const double dissipated = groundDissipation(g, c.q, 0, 0, y0, 0, y1, rule);
    EXPECT_GE(dissipated, 0.0);
    EXPECT_NEAR(work, stored + dissipated, 1e-12 * g.k * c.q * c.q)
        << c.q << " " << c.p0 << " -> " << c.p1;
    EXPECT_GE(f.force, 0.0);  // never pulls
    EXPECT_EQ(f.normal, f.force);
  }
}

TEST(GroundCrushing, TangentIsTheDerivativeOfTheForce) {
  const Ground g{0.0, 1e4, 0.0, 0.0, 0.5};
  const StepRule rule = TimeIntegrator::midPoint(0, 0).rule(0.01);
  for (const Case& c : cases(2e-3)) {
    if (std::abs(c.p1 - c.p0) < 1e-6) continue;  // the difference quotient would straddle a kink
    const double y0 = -c.p0, y1 = -c.p1, h = 1e-9;
    const double fd = -(groundContact(g, c.q, y0, y1 + h, rule).force -
                        groundContact(g, c.q, y0, y1 - h, rule).force) /
                      (2 * h);
    EXPECT_NEAR(groundContact(g, c.q, y0, y1, rule).tangent, fd, 1e-5 * g.k)
        << c.q << " " << c.p0 << " -> " << c.p1;
  }
}

TEST(GroundCrushing, TendsToTheElasticLaw) {
  const Ground elastic{0.0, 1e4, 0.0, 0.0, 1.0}, nearly{0.0, 1e4, 0.0, 0.0, 1 - 1e-12};
  const StepRule rule = TimeIntegrator::midPoint(0, 0).rule(0.01);
  for (const Case& c : cases(2e-3)) {
    const ContactForce a = groundContact(elastic, c.q, -c.p0, -c.p1, rule),
                       b = groundContact(nearly, c.q, -c.p0, -c.p1, rule);
    EXPECT_NEAR(a.force, b.force, 1e-8 * elastic.k * c.q);
    EXPECT_NEAR(a.tangent, b.tangent, 1e-6 * elastic.k);
  }
}

TEST(GroundCrushing, StaticLawUnloadsStiffAndStopsAtTheSet) {
  const Ground g{0.0, 1e4, 0.0, 0.0, 0.5};
  const StepRule rule = TimeIntegrator::statics().rule(1);
  const double q = 2e-3, set = q * (1 - 0.25);
  EXPECT_NEAR(groundContact(g, q, -q, -1.5 * q, rule).force, 1.5 * g.k * q, 1e-9);  // loading
  EXPECT_NEAR(groundContact(g, q, -q, -0.9 * q, rule).force, g.k * q - 4 * g.k * 0.1 * q, 1e-9);
  EXPECT_NEAR(groundContact(g, q, -q, -0.9 * q, rule).tangent, 4 * g.k, 1e-9);
  EXPECT_EQ(groundContact(g, q, -q, -0.99 * set, rule).force, 0.0);
}

TEST(GroundCrushing, LoadingPointFollowsTheLargestPenetrationAndIsForgottenAboveTheGround) {
  const Ground g{0.0, 1e4, 0.0, 0.0, 0.5};
  EXPECT_EQ(loadingPoint(g, 0.0, 0.0, -1e-3, 0.0, 0.0), 1e-3);
  EXPECT_EQ(loadingPoint(g, 2e-3, 0.0, -1e-3, 0.0, 0.0), 2e-3);
  EXPECT_EQ(loadingPoint(g, 2e-3, 0.0, 1e-6, 0.0, 0.0), 0.0);
  // Still moving down, or massless: the step's end.
  EXPECT_EQ(loadingPoint(g, 0.0, 2.0, -1e-3, -1.0, -0.5), 1e-3);
  EXPECT_EQ(loadingPoint(g, 0.0, 0.0, -1e-3, -1.0, 0.5), 1e-3);
  // Stored energy: the unloading branch's f^2 e^2 / (2 k).
  const double q = 2e-3, p = 0.9 * q, f = g.k * q - 4 * g.k * (q - p);
  EXPECT_NEAR(contactEnergy(g, q, -p), f * f * 0.25 / (2 * g.k), 1e-15);
}

}  // namespace
}  // namespace c2d
