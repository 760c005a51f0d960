// Member-to-member contact (core/contact/MemberContact and its pieces,
// core/contact/MemberCrossing): the pair law and its tangent, the discrete
// gradient under the mid-point scheme, the assembled tangent and pattern, and
// whole analyses: bars colliding end-on and crosswise (energy and momentum), a
// bar dropped on a fixed beam (penetration, rebound, dissipation), ruptured
// joints' pieces. The search: ContactSearchTest.cpp; step starts:
// PairStartsTest.cpp.
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

// --- the pair law -----------------------------------------------------------

PairPositions shifted(const PairPositions& q, int i, double h) {
  PairPositions r = q;
  Vec2* p[3] = {&r.x, &r.a, &r.b};
  (*p[i / 2])(i % 2) += h;
  return r;
}

// The central differences of pairContact's force with respect to the
// positions at t_n+1 (step 1e-7); ok: whether every evaluation carried a force.
PairMat pairTangentByDifferences(const PairPositions& q0, const PairPositions& q1, int side,
                                 double hc, const PairLaw& law, const StepRule& rule,
                                 double face = 0, bool* ok = nullptr) {
  const double h = 1e-7;
  PairVec fp, fm;
  PairMat fd, unused;
  bool all = true;
  for (int i = 0; i < 6; ++i) {
    all &= pairContact(q0, shifted(q1, i, h), side, hc, law, rule, false, fp, unused, nullptr, face);
    all &= pairContact(q0, shifted(q1, i, -h), side, hc, law, rule, false, fm, unused, nullptr,
                       face);
    fd.col(i) = (fp - fm) / (2 * h);
  }
  if (ok) *ok = all;
  return fd;
}

double pairEnergy(const PairPositions& q, int side, double h, double k) {
  const double p = pairPenetration(q, side, h);
  return p > 0 ? 0.5 * k * p * p : 0.0;
}

// Configurations at t_n and t_n+1 in every region: inside the span from
// either side, pushed through the centre line, beyond either end, entering and
// leaving contact.
std::vector<std::pair<PairPositions, PairPositions>> pairCases() {
  const Vec2 a(0.1, -0.05), b(1.2, 0.15);
  std::vector<std::pair<PairPositions, PairPositions>> cases;
  auto add = [&](Vec2 x0, Vec2 x1, Vec2 da = Vec2::Zero(), Vec2 db = Vec2::Zero()) {
    cases.push_back({{x0, a, b}, {x1, a + da, b + db}});
  };
  add({0.6, 0.12}, {0.62, 0.06}, {0.01, -0.02}, {-0.02, 0.015});  // above, in contact
  add({0.5, -0.2}, {0.55, 0.0}, {0.0, 0.01}, {0.01, 0.0});        // below, pushed across
  add({0.7, 0.3}, {0.68, 0.09}, {0.02, 0.0}, {0.0, -0.01});       // entering
  add({0.4, 0.07}, {0.45, 0.25}, {0.0, 0.0}, {0.01, 0.02});       // leaving
  add({0.02, -0.1}, {0.04, -0.07}, {0.01, 0.0}, {0.0, 0.0});      // beyond a
  add({1.3, 0.2}, {1.26, 0.18}, {0.0, 0.01}, {-0.015, 0.0});      // beyond b
  add({1.19, 0.26}, {1.22, 0.21}, {0.005, 0.0}, {0.0, 0.01});     // from inside to beyond b
  return cases;
}

// A dashpot (kN s/m) and the pair's rates at t_n for Newmark's (z = (x - a, b - a)).
PairLaw dampedLaw(double k, double c) {
  PairLaw law{k, c};
  law.zv << 0.4, -1.1, 0.2, 0.3;
  law.za << -3.0, 2.0, 1.0, -0.5;
  return law;
}

TEST(MemberContactPair, TangentMatchesFiniteDifferencesUnderEveryRule) {
  const double k = 3e3, hc = 0.12;
  for (const TimeIntegrator& ti :
       {TimeIntegrator::statics(), TimeIntegrator::newmark(0.25, 0.5),
        TimeIntegrator::midPoint(0, 0), TimeIntegrator::midPoint(0.2, 0)})
    for (const auto& [q0, q1] : pairCases()) {
      const StepRule rule = ti.rule(0.01);
      const int side = pairSide(q0);
      PairVec f;
      PairMat K, unused;
      const PairLaw law = dampedLaw(k, 9.0);
      if (!pairContact(q0, q1, side, hc, law, rule, true, f, K)) continue;
      bool ok = false;
      const PairMat fd = pairTangentByDifferences(q0, q1, side, hc, law, rule, 0, &ok);
      ASSERT_TRUE(ok);
      EXPECT_LT((fd - K).cwiseAbs().maxCoeff(), 1e-6 * K.cwiseAbs().maxCoeff())
          << ti.describe() << " x0 " << q0.x.transpose() << " x1 " << q1.x.transpose() << "\nK\n"
          << K << "\nFD\n"
          << fd;
      // Translation invariance: the forces on node and segment balance.
      EXPECT_LT((f.segment<2>(0) + f.segment<2>(2) + f.segment<2>(4)).norm(), 1e-12 * f.norm());
      if (rule.scheme != Scheme::MidPoint) {
        // Without the dashpot: the plain gradient of the energy.
        pairContact(q0, q1, side, hc, PairLaw{k}, rule, false, f, unused);
        PairVec g;
        const double h = 1e-7;
        for (int i = 0; i < 6; ++i)
          g(i) = (pairEnergy(shifted(q1, i, h), side, hc, k) -
                  pairEnergy(shifted(q1, i, -h), side, hc, k)) /
                 (2 * h);
        EXPECT_LT((g - f).norm(), 1e-6 * f.norm());
      }
    }
}

// A node entering contact within the step under Newmark: across the segment
// a = (0, 0), b = (1, 0) from 0.3 above to p_n+1 = delta inside the contact
// distance hc (p_n = hc - 0.3 < 0).
PairPositions entering(double delta, double hc) { return {{0.5, hc - delta}, {0, 0}, {1, 0}}; }

TEST(MemberContactPair, NewmarkDashpotRampsInWhereThePairBeginsTouching) {
  // Dashpot alone (the penalty only scales it): the force at p_n+1 = delta is
  // c w dp/dt with w = delta / |p_n+1 - p_n|, so it goes to zero with delta
  // instead of jumping to c dp/dt where the pair begins to touch.
  const double hc = 0.12, c = 9.0;
  const StepRule rule = TimeIntegrator::newmark(0.25, 0.5).rule(0.01);
  const PairPositions q0{{0.5, 0.3}, {0, 0}, {1, 0}};
  const int side = pairSide(q0);
  PairLaw law = dampedLaw(1e-9, c);
  PairVec f, fp, fm;
  PairMat K, unused;
  Eigen::Vector4d dz;  // z_n+1 - z_n, z = (x - a, b - a)
  dz << 0, hc - 0.3, 0, 0;
  const double rate =
      std::abs(rule.velocity(dz, Eigen::Vector4d(law.zv), Eigen::Vector4d(law.za))(1));
  ASSERT_GT(rate, 1.0);
  for (double delta : {1e-3, 1e-6, 1e-9}) {
    ASSERT_TRUE(pairContact(q0, entering(delta, hc), side, hc, law, rule, false, f, unused));
    EXPECT_LT(f.norm(), 10 * c * rate * delta / (0.3 - hc + delta)) << "delta " << delta;
  }
  // Deeper than the step's motion: the whole dashpot.
  ASSERT_TRUE(pairContact(q0, entering(0.2, hc), side, hc, law, rule, false, f, unused));
  EXPECT_GT(f.norm(), 0.5 * c * rate);
  // The tangent on the ramp (with the penalty and friction) against finite
  // differences.
  law = dampedLaw(3e3, c);
  law.mu = 0.5;
  law.stick = frictionStickDamping(3e3, 0.8);
  for (double delta : {0.01, 0.05}) {
    const PairPositions q1 = entering(delta, hc);
    ASSERT_TRUE(pairContact(q0, q1, side, hc, law, rule, true, f, K));
    const PairMat fd = pairTangentByDifferences(q0, q1, side, hc, law, rule);
    EXPECT_LT((fd - K).cwiseAbs().maxCoeff(), 1e-6 * K.cwiseAbs().maxCoeff())
        << "delta " << delta << "\nK\n"
        << K << "\nFD\n"
        << fd;
  }
}

TEST(MemberContactPair, MidPointForceIsADiscreteGradient) {
  // f . (q1 - q0) = U1 - U0 exactly; with a dashpot c the work exceeds it by
  // the dissipation c (<p1> - <p0>)(p1 - p0) / h >= 0.
  const double k = 3e3, hc = 0.12, dt = 0.01;
  int checked = 0;
  for (double c : {0.0, 9.0})
    for (const auto& [q0, q1] : pairCases()) {
      const StepRule rule = TimeIntegrator::midPoint(0, 0).rule(dt);
      const int side = pairSide(q0);
      PairVec f;
      PairMat K;
      if (!pairContact(q0, q1, side, hc, PairLaw{k, c}, rule, false, f, K)) continue;
      PairVec dq;
      dq << q1.x - q0.x, q1.a - q0.a, q1.b - q0.b;
      const double u0 = pairEnergy(q0, side, hc, k), u1 = pairEnergy(q1, side, hc, k);
      const double p0 = pairPenetration(q0, side, hc), p1 = pairPenetration(q1, side, hc);
      const double dissipation = c * (std::max(p1, 0.0) - std::max(p0, 0.0)) * (p1 - p0) / dt;
      EXPECT_GE(dissipation, 0.0);
      EXPECT_NEAR(f.dot(dq), u1 - u0 + dissipation, 1e-12 * k * hc * hc);
      ++checked;
    }
  EXPECT_GE(checked, 12);
}

// Laws with crushing (loading points below, inside and beyond the steps'
// penetrations) and friction (springs sticking, sliding, clamped at t_n).
std::vector<PairLaw> inelasticLaws(double k, double c) {
  std::vector<PairLaw> laws;
  for (double q : {0.0, 0.03, 0.2})
    for (double stretch : {0.0, 2e-3, -0.05}) {
      PairLaw law = dampedLaw(k, c);
      law.restitution = 0.4;
      law.q = q;
      law.mu = 0.5;
      law.stretch = stretch;
      law.stick = frictionStickDamping(k, 0.8);  // the friction's stick dashpot
      laws.push_back(law);
      law.mu = 0;  // crushing alone
      if (stretch == 0) laws.push_back(law);
      law.mu = 0.3;  // friction alone
      law.restitution = 1;
      if (q == 0) laws.push_back(law);
    }
  return laws;
}

TEST(MemberContactPair, CrushingAndFrictionTangentsMatchFiniteDifferences) {
  const double k = 3e3, hc = 0.12;
  int checked = 0;
  for (const TimeIntegrator& ti :
       {TimeIntegrator::statics(), TimeIntegrator::newmark(0.25, 0.5),
        TimeIntegrator::midPoint(0, 0), TimeIntegrator::midPoint(0.2, 0)})
    for (const PairLaw& law : inelasticLaws(k, 9.0))
      for (const auto& [q0, q1] : pairCases()) {
        const StepRule rule = ti.rule(0.01);
        const int side = pairSide(q0);
        PairVec f;
        PairMat K;
        if (!pairContact(q0, q1, side, hc, law, rule, true, f, K) || K.isZero()) continue;
        const PairMat fd = pairTangentByDifferences(q0, q1, side, hc, law, rule);
        EXPECT_LT((fd - K).cwiseAbs().maxCoeff(), 1e-5 * K.cwiseAbs().maxCoeff())
            << ti.describe() << " q " << law.q << " mu " << law.mu << " stretch " << law.stretch
            << " x0 " << q0.x.transpose() << " x1 " << q1.x.transpose() << "\nK\n"
            << K << "\nFD\n"
            << fd;
        EXPECT_LT((f.segment<2>(0) + f.segment<2>(2) + f.segment<2>(4)).norm(), 1e-12 * f.norm());
        ++checked;
      }
  // (Inside a crushed set neither the law nor the dashpot acts: no tangent.)
  EXPECT_GE(checked, 280);
}

TEST(MemberContactPair, HeldSideTangentsMatchFiniteDifferences) {
  // A node held on either side (the pairs of a ruptured joint), in every
  // region: on the wrong side inside the span, beyond either end, and inside
  // the span near either end (the end faces: their ramp within 0.01 face,
  // their cap at the face).
  const double k = 3e3, hc = 0.12, face = 0.3;
  std::vector<std::pair<PairPositions, PairPositions>> cases = pairCases();
  const Vec2 a(0.1, -0.05), b(1.2, 0.15);
  const Vec2 t = (b - a).normalized(), n(-t.y(), t.x());
  for (double along : {0.0015, 0.006, 0.25, 0.3015})
    for (double across : {-0.006, 0.003}) {
      cases.push_back({{a - 0.002 * t, a, b}, {a + along * t + across * n, a, b}});
      cases.push_back({{b + 0.002 * t, a, b}, {b - along * t + across * n, a + 0.001 * n, b}});
    }
  int checked = 0;
  for (const TimeIntegrator& ti : {TimeIntegrator::statics(), TimeIntegrator::midPoint(0.2, 0)})
    for (const PairLaw& law : inelasticLaws(k, 9.0))
      for (const auto& [q0, q1] : cases)
        for (int side : {1, -1}) {
          const StepRule rule = ti.rule(0.01);
          PairVec f;
          PairMat K, unused;
          if (!pairContact(q0, q1, side, hc, law, rule, true, f, K, nullptr, face) || K.isZero())
            continue;
          const PairMat fd = pairTangentByDifferences(q0, q1, side, hc, law, rule, face);
          EXPECT_LT((fd - K).cwiseAbs().maxCoeff(), 1e-5 * K.cwiseAbs().maxCoeff())
              << ti.describe() << " side " << side << " x0 " << q0.x.transpose() << " x1 "
              << q1.x.transpose();
          ++checked;
        }
  EXPECT_GE(checked, 100);
}

TEST(MemberContactPair, HeldSideIsContinuousAroundTheSegmentsEnds) {
  // Held above a segment along x from 0 to 1: a node below it is pushed up
  // inside the span (p = h + |d|) and, beyond the end, by
  // p = h + (d^2 - e^2) / rho (e the distance beyond the end, rho from the end
  // point), which meets the span's at the end and the rounded end's (h - rho)
  // on the line, in value and in slope; above it the rounded end holds.
  const Vec2 a(0, 0), b(1, 0);
  const double h = 0.01, eps = 1e-9;
  auto p = [&](double x, double y) { return pairPenetration({Vec2(x, y), a, b}, 1, h, 0.1); };
  EXPECT_NEAR(p(1 - eps, -0.003), h + 0.003, 1e-8);
  EXPECT_NEAR(p(1 + eps, -0.003), h + 0.003, 1e-8);
  EXPECT_NEAR(p(1.004, -0.003), h + (0.003 * 0.003 - 0.004 * 0.004) / 0.005, 1e-12);
  EXPECT_NEAR(p(1.004, -eps), h - 0.004, 1e-8);
  EXPECT_NEAR(p(1.004, eps), h - 0.004, 1e-8);
  EXPECT_NEAR(p(-0.002, -0.005), h + (0.005 * 0.005 - 0.002 * 0.002) / std::hypot(0.002, 0.005),
              1e-12);
  EXPECT_NEAR(p(1.003, 0.004), h - 0.005, 1e-12);  // rounded end on its side
  // The slopes on either side of the line beyond the end (where the pieces of
  // a ruptured joint lie end to end) and of the end's normal below the span.
  const double step = 1e-8, off = 1e-7;
  auto slope = [&](double x, double y, double dx, double dy) {
    return (p(x + step * dx, y + step * dy) - p(x - step * dx, y - step * dy)) / (2 * step);
  };
  for (const Vec2& dir : {Vec2(1, 0), Vec2(0, 1)}) {
    EXPECT_NEAR(slope(1.004, -off, dir.x(), dir.y()), slope(1.004, off, dir.x(), dir.y()), 1e-3);
    EXPECT_NEAR(slope(-0.004, -off, dir.x(), dir.y()), slope(-0.004, off, dir.x(), dir.y()), 1e-3);
    EXPECT_NEAR(slope(1 - off, -0.003, dir.x(), dir.y()), slope(1 + off, -0.003, dir.x(), dir.y()),
                1e-3);
  }
  // Not held: the rounded end on both sides.
  EXPECT_NEAR(pairPenetration({Vec2(1.004, -0.003), a, b}, 1, h), h - 0.005, 1e-12);
}

TEST(MemberContactPair, AHeldNodeMeetsTheSegmentsEndFaces) {
  // Held above a segment along x from 0 to 1 at the reach h = 0 (a ruptured
  // joint's pair, its whole distance offset), face 0.1 (w = 0.001): a node on
  // the line x inside the span from either end penetrates by x^2 / (2 w)
  // within w, x - w / 2 beyond, up to the face, and is pushed back out along
  // the segment as well as up; one clear of the line by the face is not
  // pushed; not held, the node on the line has p = h = 0.
  const Vec2 a(0, 0), b(1, 0);
  const double face = 0.1, w = 0.001;
  auto p = [&](double x, double y) { return pairPenetration({Vec2(x, y), a, b}, 1, 0.0, face); };
  EXPECT_NEAR(p(0.0005, 0), 0.0005 * 0.0005 / (2 * w), 1e-15);
  EXPECT_NEAR(p(0.003, 0), 0.003 - w / 2, 1e-15);
  EXPECT_NEAR(p(0.997, 0), 0.003 - w / 2, 1e-15);
  EXPECT_NEAR(p(0.003, -0.002), 0.003 - w / 2 + 0.002, 1e-15);
  EXPECT_NEAR(p(0.2, 0), face, 1e-15);
  EXPECT_LT(p(0.2, 0.1001), 0.0);
  EXPECT_EQ(pairPenetration({Vec2(0.003, 0), a, b}, 1, 0.0), 0.0);
  // The force on the node, -k grad p: out along the segment at the end a
  // (-x) and at the end b (+x), and up.
  const double step = 1e-7;
  auto grad = [&](double x, double y) {
    return Vec2((p(x + step, y) - p(x - step, y)) / (2 * step),
                (p(x, y + step) - p(x, y - step)) / (2 * step));
  };
  EXPECT_NEAR(grad(0.003, 0).x(), 1.0, 1e-6);
  EXPECT_NEAR(grad(0.997, 0).x(), -1.0, 1e-6);
  EXPECT_NEAR(grad(0.003, 0).y(), -1.0, 1e-6);
}

TEST(MemberContactPair, MidPointWorkIsStoredPlusDissipatedEnergy) {
  // f . (q1 - q0) = (U1 - U0) + crushing + dashpot + friction's sliding,
  // every dissipated part >= 0, with U the crushing law's energy at the loading
  // point max(q, p) and the friction spring's k s^2 / 2.
  const double k = 3e3, hc = 0.12;
  int checked = 0;
  const double dt = 0.01;
  for (double c : {0.0, 9.0})
    for (const PairLaw& given : inelasticLaws(k, c))
      for (const auto& [q0, q1] : pairCases()) {
        const StepRule rule = TimeIntegrator::midPoint(0, 0).rule(dt);
        const int side = pairSide(q0);
        // A loading point is kept only while in contact.
        PairLaw law = given;
        if (pairPenetration(q0, side, hc) <= 0) law.q = 0;
        PairVec f;
        PairMat K;
        PairOutcome out;
        if (!pairContact(q0, q1, side, hc, law, rule, false, f, K, &out)) continue;
        PairVec dq;
        dq << q1.x - q0.x, q1.a - q0.a, q1.b - q0.b;
        const double p0 = out.p0, p1 = out.p1;
        const double qn = crushingLoadingPoint(law.q, p0);
        const double u0 = crushingEnergy(k, law.restitution, law.q, p0) +
                          springFrictionEnergy(k, law.stretch);
        const double u1 = crushingEnergy(k, law.restitution, qn, p1) +
                          springFrictionEnergy(k, out.stretch);
        const double crushing = CrushingLaw(k, law.restitution, law.q).dissipated(p0, p1);
        const double set = std::max(law.q, p0) * (1 - law.restitution * law.restitution);
        const double damping =
            c * (std::max(p1 - set, 0.0) - std::max(p0 - set, 0.0)) * (p1 - p0) / dt;
        EXPECT_GE(crushing, 0.0);
        EXPECT_GE(damping, 0.0);
        EXPECT_GE(out.slipped, 0.0);
        EXPECT_NEAR(f.dot(dq), u1 - u0 + crushing + damping + out.slipped, 1e-11 * k * hc * hc)
            << "q " << law.q << " mu " << law.mu << " stretch " << law.stretch << " x0 "
            << q0.x.transpose();
        ++checked;
      }
  EXPECT_GE(checked, 150);
}

TEST(MemberContactPair, PenetrationFromTheSideAtTheLastCommittedState) {
  const Vec2 a(0, 0), b(1, 0);
  const double h = 0.1;
  // Above the segment at t_n: 0.05 above is 0.05 deep, 0.05 below is 0.15 deep.
  const PairPositions above{Vec2(0.5, 0.05), a, b}, below{Vec2(0.5, -0.05), a, b};
  const int side = pairSide(above);
  EXPECT_EQ(side, 1);
  EXPECT_NEAR(pairPenetration(above, side, h), 0.05, 1e-15);
  EXPECT_NEAR(pairPenetration(below, side, h), 0.15, 1e-15);
  EXPECT_NEAR(pairPenetration(below, pairSide(below), h), 0.05, 1e-15);
  // Rounded ends.
  EXPECT_NEAR(pairPenetration({Vec2(-0.06, 0.08), a, b}, side, h), 0.0, 1e-15);
  EXPECT_NEAR(pairPenetration({Vec2(1.03, -0.04), a, b}, side, h), 0.05, 1e-15);
}

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

TEST(MemberContactModel, APairInMemoryOutOfReachLetsGoOfItsFrictionSpring) {
  // A commit's passes visit the pairs that may touch and those in memory
  // (MemberContact::touching): a pair whose node has left the segment's reach
  // with its friction spring stretched lets go of it, the spring's energy
  // counted as dissipated, and its memory is dropped.
  Model m;
  m.materials()[1] = rod(1, 1e4, 1e4, 10, 1.0, 2.5e-3 / 3);  // r = 0.05
  newRod(m, Vec2(0, 0), Vec2(2, 0), 8);
  const int bar = newRod(m, Vec2(0.9, 0.2), Vec2(0.9, 1.2), 4);  // its lowest node 0.2 above
  const double k = 1e3, stretch = 0.01;
  m.memberContact() = MemberContactData{k, 0, -1, 1, 0.5};
  Assembler as(m);
  as.refresh();
  MemberContact& mc = *as.memberContact();
  State s;
  s.resize(m.numNodes());
  const std::vector<ContactPair>& candidates = mc.candidates(m, s);
  const auto pair = std::find_if(candidates.begin(), candidates.end(),
                                 [&](const ContactPair& p) { return p.node == bar; });
  ASSERT_NE(pair, candidates.end());  // a candidate of the search's margin
  s.pairs = {PairMemory{pair->key(), 0.0, 0.0, stretch, pair->h, 0}};
  mc.openPairs(m, s);
  const StepRule rule = TimeIntegrator::midPoint(0, 0).rule(0.01);
  EXPECT_NEAR(as.contactDissipation(s, rule), springFrictionEnergy(k, stretch), 1e-15);
  as.commitContact(s);
  EXPECT_TRUE(s.pairs.empty());
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

// Two rods meeting end to end at x = 1 at a right angle, their end nodes
// coincident but not tied (a joint that ruptured): rod a along x from 0 to 1,
// rod b up from (1, 0), four elements each; section radius sqrt(3 I / A) =
// 0.0158 (contact distance 0.0316), member contact k = 1e3.
// Statics, no loads.
struct RupturedCorner {
  Model m;
  int a = 0, b = 0;
  std::unique_ptr<Assembler> as;
  State s;
  StepRule rule = TimeIntegrator::statics().rule(1.0);
  Eigen::VectorXd factors;
  RupturedCorner() {
    m.materials()[1] = rod(1, 1e4, 1e4, 1e4, 10, 2.5e-3 / 3);
    a = newRod(m, Vec2(0, 0), Vec2(1, 0), 4);
    b = newRod(m, Vec2(1, 0), Vec2(1, 1), 4);
    m.memberContact() = MemberContactData{1e3, 0, -1};
    as = std::make_unique<Assembler>(m);
    as->refresh();
    s.resize(m.numNodes());
    factors = Eigen::VectorXd::Zero(3 * m.numNodes());
  }
};

TEST(MemberContactModel, MembersSetFreeInsideTheirDistanceStartAtZeroForce) {
  // The ruptured corner: each end node lies on the
  // other rod's end, inside the contact distance. They start at zero force
  // (the offsets); one end moved into the other rod's span past its centre
  // line is pushed back.
  RupturedCorner c;
  auto& [m, a, b, corner, s, rule, factors] = c;
  Assembler& as = *corner;
  as.openContacts(s);
  ASSERT_FALSE(s.pairs.empty());
  for (const PairMemory& p : s.pairs) EXPECT_GT(p.offset, 0.0);
  ASSERT_TRUE(as.assemble(s, rule, factors, false));
  EXPECT_EQ(as.contactForces().cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(as.contactEnergy(s), 0.0);
  // Rod b's end node (b) moved down into rod a's last element, past its
  // centre line (it came from above): pushed back up.
  s.u(3 * b + 0) = -0.1;
  s.u(3 * b + 1) = -0.01;
  ASSERT_TRUE(as.assemble(s, rule, factors, false));
  EXPECT_GT(as.contactEnergy(s), 0.0);
}

TEST(MemberContactModel, ARupturedJointsEndNodeIsHeldOnItsMembersSide) {
  // The ruptured corner: rod b's end node lies on rod a's centre
  // line, at its end, so its side is a toss-up; it is held on the side where
  // rod b lies (above). Rod b moved 1 mm down, it is pushed back, and a
  // commit there does not turn it to the wrong side: the contact still pushes
  // up at the next step. Clear of the line, the pair lets the held side go.
  RupturedCorner c;
  auto& [m, a, b, corner, s, rule, factors] = c;
  Assembler& as = *corner;
  as.openContacts(s);
  // The pair (node b, rod a's last element) and (rod a's end node, rod b's first).
  const int lastA = 3, firstB = 4;
  auto pairOf = [&](int node, int element) -> const PairMemory* {
    for (const PairMemory& p : c.s.pairs)
      if (p.key == ContactPair{node, element}.key()) return &p;
    return nullptr;
  };
  ASSERT_NE(pairOf(b, lastA), nullptr);
  EXPECT_EQ(pairOf(b, lastA)->side, 1);
  ASSERT_NE(pairOf(a + 4, firstB), nullptr);
  EXPECT_EQ(pairOf(a + 4, firstB)->side, 1);  // rod a lies left of rod b (up its axis)
  for (int n = b; n <= b + 4; ++n) s.u(3 * n + 1) = -0.001;  // rod b moved down 1 mm
  ASSERT_TRUE(as.assemble(s, rule, factors, false));
  const double below = as.contactEnergy(s);
  // Rod a's end node is now 1 mm inside rod b's first element, on its line:
  // it meets that element's end face (x - w / 2, w = 0.01 h).
  const double face = 0.001 - 0.005 * 2 * std::sqrt(2.5e-4);
  EXPECT_NEAR(below, 0.5 * 1e3 * (0.001 * 0.001 + face * face), 1e-12);
  as.commitContact(s);
  s.commit();
  EXPECT_EQ(pairOf(b, lastA)->side, 1);
  ASSERT_TRUE(as.assemble(s, rule, factors, false));
  EXPECT_NEAR(as.contactEnergy(s), below, 1e-15);
  EXPECT_EQ(as.pushedThrough(), 0);
  // Above the line by 2 mm it is still held; clear of it by a quarter of the
  // contact distance (0.25 * 0.0316 m), the side at t_n takes over.
  for (const auto& [y, held] : {std::pair{0.002, 1}, std::pair{0.01, 0}}) {
    for (int n = b; n <= b + 4; ++n) s.u(3 * n + 1) = y;
    ASSERT_TRUE(as.assemble(s, rule, factors, false));
    as.commitContact(s);
    s.commit();
    ASSERT_NE(pairOf(b, lastA), nullptr);
    EXPECT_EQ(pairOf(b, lastA)->side, held) << y;
  }
}

TEST(MemberContactModel, RupturedJointsPiecesPressedTipToTipDoNotPassEachOther) {
  // A ruptured joint's two pieces lying end to end, kinked 0.1 rad at the
  // joint (each end node on the other's end, held on the side its own piece
  // lies), pressed together along their axes: piece a clamped at its far
  // end, piece b's far end on a roller pushed by 2 kN (contact k = 2e3,
  // distance 0.035 m). With the whole distance offset the pairs' reach is
  // zero there: b's end node slid into a's span along a's line (pushed only
  // across it, by k 0.1 x), and the pieces ended crossed, their tips 0.19 m
  // past each other. The held end faces push it back out along the segment:
  // the tips overlap by less than the force over k (0.6 mm).
  Model m;
  m.materials()[1] = rod(1, 1e4, 1e4, 50.0, 1.0, 1e-4);  // r = 0.0173
  const int a = newRod(m, Vec2(-1, 0), Vec2(0, 0), 4);
  const int b = newRod(m, Vec2(0, 0), Vec2(1, -0.1), 4);
  m.bound(a) = {1, 1, 1};
  m.bound(b + 4) = {0, 1, 1};
  m.force(b + 4) = {-2.0, 0, 0};
  m.memberContact() = MemberContactData{2e3, 1, -1};
  Analysis an(m);
  an.setLoadFunction(1, ProportionalLoad::table({{0.0, 0.0}, {0.2, 1.0}, {10.0, 1.0}}));
  an.setIntegrator(TimeIntegrator::midPoint(0.1, 0));
  an.setDt(0.01);
  State& s = an.state();
  for (int step = 0; step < 100; ++step) {
    ASSERT_TRUE(solveStep(an)) << "step " << step;
    an.commit();
  }
  EXPECT_TRUE(findCrossings(m, s).empty());
  const double overlap = position(m, s, a + 4).x() - position(m, s, b).x();
  EXPECT_LT(overlap, 2.0 / 2e3);
}

TEST(MemberContactModel, ACommitReleasesWhatAHeldPairNoLongerStores) {
  // Rod b's end node, held above rod a, ends a step beyond rod a's end and
  // below its line (the held side's wedge presses it: p = (d^2 - e^2) / rho
  // > 0) but farther from the segment than the contact distance: at the
  // committed state alone the pair is apart. What it stored is released at
  // the commit, so that the energy before the commit less the released
  // equals the energy after it. (Rod a's end node, inside rod b's tilted
  // first element by 5.5 cm, is 3.3 cm from its line: beyond its end face's
  // cap, the contact distance 3.16 cm.)
  RupturedCorner c;
  auto& [m, a, b, corner, s, rule, factors] = c;
  Assembler& as = *corner;
  as.openContacts(s);
  s.u(3 * b + 0) = 0.04;
  s.u(3 * b + 1) = -0.05;
  ASSERT_TRUE(as.assemble(s, rule, factors, false));
  const double before = as.contactEnergy(s);
  EXPECT_GT(before, 0.0);
  const double released = as.commitContact(s);
  s.commit();
  EXPECT_NEAR(before - released, as.contactEnergy(s), 1e-12);
  EXPECT_EQ(as.contactEnergy(s), 0.0);
}

TEST(MemberContactModel, AHeldPairsTurnInsideTheStepIsReleasedOnce) {
  // The ruptured corner with crushing pairs (e = 0.5): rod b's end node, held
  // above rod a, ends the step 1 cm below its centre line, having moved down
  // at t_n and up at t_n+1: the pair's turn fell inside the step, and its
  // loading point becomes the peak its mass came back from. The energy
  // before the commit less the released must be the energy after it (the
  // crushing the new loading point took was booked twice: the account's
  // balance stood off by that much at such commits).
  RupturedCorner c;
  auto& [m, a, b, corner, s, rule, factors] = c;
  m.memberContact() = MemberContactData{1e3, 0, -1, 0.5, 0};
  Assembler& as = *corner;
  as.restartContactSearch();
  as.openContacts(s);
  s.u(3 * b + 1) = -0.01;
  s.vn(3 * b + 1) = -1.0;
  s.v(3 * b + 1) = 0.5;
  ASSERT_TRUE(as.assemble(s, rule, factors, false));
  const double before = as.contactEnergy(s);
  EXPECT_GT(before, 0.0);
  const double released = as.commitContact(s);
  s.commit();
  const double after = as.contactEnergy(s);
  EXPECT_GT(released, 0.0);  // the turn's crushing
  EXPECT_LT(after, before);
  EXPECT_NEAR(before - released, after, 1e-12);
}

TEST(MemberContactModel, OpeningPairsKeepsOneMemoryPerPair) {
  // The ruptured corner, the pair (rod b's end node, rod a's last element)
  // already in memory: opening the others (whose keys sort before it) must
  // not give it a second memory.
  RupturedCorner c;
  auto& [m, a, b, corner, s, rule, factors] = c;
  Assembler& as = *corner;
  const std::uint64_t known = ContactPair{b, 3}.key();
  s.pairs.push_back({known, 0.0, 0.01, 0.0, 0.0316, 0});
  as.openContacts(s);
  ASSERT_GT(s.pairs.size(), 1u);
  int copies = 0;
  for (const PairMemory& p : s.pairs) copies += p.key == known;
  EXPECT_EQ(copies, 1);
  EXPECT_TRUE(std::is_sorted(s.pairs.begin(), s.pairs.end(),
                             [](const PairMemory& x, const PairMemory& y) { return x.key < y.key; }));
}

TEST(MemberContactModel, ANodePushedPastTheCentreLineReleasesWhatItsOldSideStored) {
  // A rod and a rod standing on it whose lower end ends the step 0.01 below
  // the first rod's centre line: seen from above its penetration is h + 0.01,
  // from below h - 0.01 (h the contact distance). The commit sees it from
  // below from then on, and returns the energy k ((h + 0.01)^2 - (h - 0.01)^2)
  // / 2 as released; the stored energy drops by as much.
  Model m;
  m.materials()[1] = rod(1, 1e4, 1e4, 1e4, 10, 2.5e-3 / 3);
  newRod(m, Vec2(0, 0), Vec2(2, 0), 2);
  const int stand = newRod(m, Vec2(0.5, 1.0), Vec2(0.5, 2.0), 2);
  const double k = 1e3;
  m.memberContact() = MemberContactData{k, 0, -1};
  Assembler as(m);
  as.refresh();
  const double h = 2 * as.memberContact()->radius(0);
  ASSERT_GT(h, 0.02);
  State s;
  s.resize(m.numNodes());
  for (int n = stand; n < stand + 3; ++n) {
    s.un(3 * n + 1) = -0.99;  // 0.01 above the centre line
    s.u(3 * n + 1) = -1.01;   // 0.01 below it
  }
  const Eigen::VectorXd factors = Eigen::VectorXd::Zero(3 * m.numNodes());
  ASSERT_TRUE(as.assemble(s, TimeIntegrator::statics().rule(1.0), factors, false));
  const double above = h + 0.01, below = h - 0.01;
  const double before = as.contactEnergy(s);
  EXPECT_NEAR(before, 0.5 * k * above * above, 1e-12);
  const double released = as.commitContact(s);
  EXPECT_NEAR(released, 0.5 * k * (above * above - below * below), 1e-12);
  EXPECT_EQ(as.pushedThrough(), 1);
  s.commit();
  EXPECT_NEAR(as.contactEnergy(s), before - released, 1e-12);
}

TEST(MemberContactDeck, ZeroStiffnessSwitchesMemberContactOff) {
  // decks/collapse/bar_on_beam.inp with MEMBers,,0 (and values a study keeps
  // for when it turns the contact on): the echo says the contact is off and
  // its other values unused, and the bar falls through the beam as if free
  // (g t^2 / 2 after 0.24 s), where with contact it rebounds.
  std::ifstream in(std::string(C2D_SOURCE_DIR) + "/decks/collapse/bar_on_beam.inp");
  std::stringstream text;
  text << in.rdbuf();
  std::string deck = text.str();
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

// --- crossings ---------------------------------------------------------------

TEST(MemberCrossing, ReportsCrossingMembersOnly) {
  Model m;
  m.materials()[1] = rod(1, 1e4, 1e4, 50.0, 1.0, 1e-4);
  newRod(m, Vec2(0, 0), Vec2(2, 0), 2);           // elements 0, 1
  newRod(m, Vec2(1.6, -0.5), Vec2(1.6, 0.7), 1);  // element 2 crosses element 1
  newRod(m, Vec2(0.2, 0.1), Vec2(0.8, 0.1), 1);   // element 3: parallel, above element 0
  newRod(m, Vec2(2, 0), Vec2(2.5, 0.0), 1);       // element 4 touches element 1's end
  State s;
  s.resize(m.numNodes());
  auto crossings = findCrossings(m, s);
  ASSERT_EQ(crossings.size(), 1u);
  EXPECT_EQ(crossings[0].first, 1);
  EXPECT_EQ(crossings[0].second, 2);
  // Where: at (1.6, 0), 0.4 m from element 1's node at (2, 0) and 0.5 m from
  // element 2's node at (1.6, -0.5).
  EXPECT_NEAR(crossings[0].point.x(), 1.6, 1e-14);
  EXPECT_NEAR(crossings[0].point.y(), 0.0, 1e-14);
  EXPECT_EQ(crossings[0].nearNode[0], 2);
  EXPECT_NEAR(crossings[0].fromNode[0], 0.4, 1e-14);
  EXPECT_EQ(crossings[0].nearNode[1], 3);
  EXPECT_NEAR(crossings[0].fromNode[1], 0.5, 1e-14);
  // Move element 3 down through element 0: now it crosses too.
  s.u(3 * 5 + 1) = -0.2;
  crossings = findCrossings(m, s);
  ASSERT_EQ(crossings.size(), 2u);
  EXPECT_EQ(crossings[0].first, 0);
  EXPECT_EQ(crossings[0].second, 3);
}

TEST(MemberCrossing, TipsPressedTogetherDoNotCross) {
  // Section radius sqrt(3 I / A) = 0.0173, so tips within 5 % of 0.0346 m
  // (1.7 mm) of the crossing are pressed together, not through each other.
  Model m;
  m.materials()[1] = rod(1, 1e4, 1e4, 50.0, 1.0, 1e-4);
  newRod(m, Vec2(3, 0), Vec2(4, 0), 1);                   // element 0
  const int q = newRod(m, Vec2(3.001, 0.5), Vec2(3.0005, -0.0005), 1);  // its tip 0.5 mm under
  State s;
  s.resize(m.numNodes());
  EXPECT_TRUE(findCrossings(m, s).empty());
  s.u(3 * (q + 1) + 1) = -0.0095;  // the tip 10 mm under: through
  ASSERT_EQ(findCrossings(m, s).size(), 1u);
}

}  // namespace
}  // namespace c2d
