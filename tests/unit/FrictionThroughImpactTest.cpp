// Coulomb friction through an impact (verification V14): a rigid bar landing
// flat at 19.8 m/s, 3.96 m/s sideways, on GROUnd,,0,2e5,1,0.5,0.3 (zeta = 1,
// mu = 0.5, e = 0.3) under gravity tilted by 0.2 g < mu g. Over its first
// contact the friction's impulse is at most mu times the normal impulse and
// enough to stop it (0.38 mu N), and it sticks where it lands, within 0.05 m
// (its bounce of 0.07 m under the tilt carries it 0.05 m; the stick
// element's return -0.07 m), at the steps 0.01, 0.005 and 0.001 s under the
// mid-point scheme (DYNAmic,ENERgy) and Newmark's. Before the stick
// element's dashpot (core/contact/SpringFriction.h) friction took 0.29 mu N,
// the stick spring too soft to build mu N within the 2 ms contact, and the
// bar came to rest 0.51 m on (docs/history.md, "Ground friction").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "ContactTestSupport.h"

namespace c2d::test {
namespace {

struct Landing {
  double rest = 0;      // horizontal position where it rests at t = 1.5 s, from its start, m
  double speed = 0;     // its horizontal speed then, m/s
  double apex = 0;      // highest point after the first contact, m
  double sideways = 0;  // friction's impulse over the first contact / mu the normal one
  bool solved = true;
};

// One step by Newton iterations with the line search (TANG,LINE).
bool solveWithLineSearch(Analysis& an) {
  if (!an.advance()) return false;
  IterationInfo info;
  for (int i = 0; i < 60; ++i) {
    if (!an.iterate(true, false, info)) return false;
    if (info.converged) return true;
    if (info.subStep) i = -1;
  }
  return false;
}

// members: on a held beam 13 m long instead of the ground (MEMBers with the
// ground's k, zeta, e and mu; the bar's radius 0.2 m and the beam's 0.3 m).
Landing land(const TimeIntegrator& ti, double dt, bool members = false) {
  const double mu = 0.5, gx = 0.2 * kGravity;
  Model m;
  m.materials()[1] = rod(1, 3.6e10, 1.2e10, 4.8e8, 0.3, 0.004);  // 0.3 t/m, rigid
  double y0 = 0;  // where contact begins
  if (members) {
    m.materials()[2] = rod(2, 1e12, 1e12, 1e10, 1.0, 0.03);  // r = 0.3
    const int beam = newRod(m, Vec2(-5, 0), Vec2(8, 0), 1, 2);
    for (int n = beam; n < beam + 2; ++n) m.bound(n) = {1, 1, 1};
    y0 = 0.5;
    m.memberContact() = MemberContactData{2e5, 1.0, -1, 0.3, mu};
  } else {
    m.ground() = Ground{0.0, 2e5, 1.0, mu, 0.3};
  }
  const int first = newRod(m, Vec2(0, y0 + 1e-6), Vec2(3, y0 + 1e-6), 1);
  m.gravity() = Vec2(gx, -kGravity);
  Analysis an(m);
  an.setIntegrator(ti);
  an.setDt(dt);
  State& s = an.state();
  s.resize(m.numNodes());
  for (int n = first; n < first + 2; ++n) s.v.segment<2>(3 * n) = Vec2(3.96, -19.8);
  s.vn = s.v;
  Landing out;
  const double x0 = position(m, s, first).x();
  // The first contact: from the start to the first commit out of the ground
  // and rising; its impulses from the bar's change of momentum less gravity's.
  bool inFirst = true;
  an.onCommit = [&] {
    const double y = position(m, s, first).y() - y0;
    if (inFirst && y > 0 && s.v(3 * first + 1) > 0) {
      inFirst = false;
      const double tangential = -(s.v(3 * first) - 3.96 - gx * s.tn);
      const double normal = s.v(3 * first + 1) + 19.8 + kGravity * s.tn;
      out.sideways = tangential / (mu * normal);
    }
    if (!inFirst) out.apex = std::max(out.apex, y);
  };
  const int steps = static_cast<int>(std::lround(1.5 / dt));
  for (int i = 0; i < steps; ++i)
    if (!solveWithLineSearch(an) || !an.commit()) {
      out.solved = false;
      break;
    }
  out.rest = position(m, s, first).x() - x0;
  out.speed = std::abs(s.v(3 * first));
  return out;
}

TEST(FrictionThroughImpact, ALandingBarSticksWhereverTheStep) {
  for (const auto& [ti, name] : {std::pair{TimeIntegrator::midPoint(0, 0), "mid-point"},
                                 std::pair{TimeIntegrator::newmark(0.25, 0.5), "Newmark"}}) {
    for (double dt : {0.001, 0.005, 0.01}) {
      const Landing l = land(ti, dt);
      std::printf("%s dt %.3f: rests %.4f m on, apex %.4f m, friction impulse %.3f mu N\n", name,
                  dt, l.rest, l.apex, l.sideways);
      ASSERT_TRUE(l.solved) << name << " dt " << dt;
      EXPECT_LE(l.sideways, 1.0 + 1e-6) << name << " dt " << dt;  // Coulomb
      // It stops over its first contact: Coulomb's impulse (0.38 mu N stops
      // it) and no more than a tenth of its sideways speed back.
      EXPECT_GT(l.sideways, 0.35) << name << " dt " << dt;
      EXPECT_LT(l.sideways, 0.42) << name << " dt " << dt;
      // It sticks where it lands (0.51 m on before, at every step), at rest;
      // Newmark's trapezoid keeps the stick spring's ringing unresolved by the
      // step of 0.01 (its period 9.4 ms) at a few cm/s, in place.
      EXPECT_LT(std::abs(l.rest), 0.05) << name << " dt " << dt;
      EXPECT_LT(l.speed, ti.kind == TimeIntegrator::Kind::MidPoint || dt < 0.01 ? 0.01 : 0.05)
          << name << " dt " << dt;
    }
  }
}

TEST(FrictionThroughImpact, ALandingBarSticksOnAMember) {
  for (double dt : {0.001, 0.01}) {
    const Landing l = land(TimeIntegrator::midPoint(0, 0), dt, true);
    std::printf("on a beam, dt %.3f: rests %.4f m on, apex %.4f m, friction impulse %.3f mu N\n",
                dt, l.rest, l.apex, l.sideways);
    ASSERT_TRUE(l.solved) << dt;
    EXPECT_LE(l.sideways, 1.0 + 1e-6) << dt;
    EXPECT_GT(l.sideways, 0.35) << dt;
    EXPECT_LT(std::abs(l.rest), 0.05) << dt;
    EXPECT_LT(l.speed, 0.01) << dt;
  }
}

}  // namespace
}  // namespace c2d::test
