// One member contact pair's law (core/contact/PairContact): its tangent against
// finite differences under every rule, the discrete gradient under the
// mid-point scheme and its work identity with crushing and friction, the held
// side of a ruptured joint's pair and its end faces, the side at t_n.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/contact/CrushingLaw.h"
#include "core/contact/PairContact.h"
#include "core/contact/SpringFriction.h"
#include "solvers/TimeIntegrator.h"

namespace c2d {
namespace {

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

}  // namespace
}  // namespace c2d
