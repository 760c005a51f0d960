// The end-force cantilever of verification.md V3 (paper Fig. 13) under tip
// displacement control, solved by the static driver (TANG,LINE,1) with full
// steps of 0.02 m and no step cutting: every step converges within 20 Newton
// iterations, also the steps in which elements near the clamp cross My (the
// hardening modulus drops from Kh1 = 29400 to Kh2 = 272 within one step) and
// the step whose hinge event is located inside the step, and the force follows
// the closed form of the discretized problem (cantilever_force.inp derives it).
// Plain Newton cycles in the second step: the elastic predictor puts four
// elements past My, the Kh2 tangent of those sends the correction past their
// reverse yield surface, and the law, saturating both ways, gives a two-cycle.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

#include "core/Hinge.h"
#include "core/Model.h"
#include "elements/InelasticFrame.h"
#include "solvers/Analysis.h"
#include "solvers/ProportionalLoad.h"
#include "tests/unit/V2Material.h"

namespace c2d {
namespace {

using test::v2::kappaOf;
using test::v2::kEI;
using test::v2::kKs;
// The V2 laws with the force case's ultimate moment (verification.md).
constexpr double kGA = 1.25e6, kMu = 374, kL = 2.5;

// Closed form of the n-element cantilever (midpoint moments M_i = P (L - x_i)).
struct Discrete {
  int n;
  double l() const { return kL / n; }
  double arm(int i) const { return kL - (i + 0.5) * l(); }
  double pu() const { return kMu / arm(0); }
  double vPre(double P) const {
    double v = P * kL / kGA;
    for (int i = 0; i < n; ++i) v += l() * kappaOf(P * arm(i)) * arm(i);
    return v;
  }
  double slope() const {
    double c = kL / kGA;
    for (int i = 0; i < n; ++i) c += l() * arm(i) * arm(i) / kEI;
    return 1.0 / (c + arm(0) * arm(0) / kKs);
  }
  double force(double v) const {
    if (v > vPre(pu())) return std::max(0.0, pu() + slope() * (v - vPre(pu())));
    double lo = 0, hi = pu();
    for (int k = 0; k < 200; ++k) {
      const double mid = 0.5 * (lo + hi);
      (vPre(mid) < v ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  }
};

MaterialSet material() { return test::v2::material(1, kGA, Kinematics::Small, kMu); }

Model cantilever(int n, double vMax) {
  Model m;
  m.materials()[1] = material();
  m.resizeNodes(n + 1);
  for (int i = 0; i <= n; ++i) m.setCoord(i, Vec2(kL * i / n, 0));
  for (int e = 0; e < n; ++e)
    m.setElement(e, std::make_unique<InelasticFrame>(m.materials()[1], std::array{e, e + 1}, m.coord(e),
                                                     m.coord(e + 1)));
  m.bound(0) = {1, 1, 1};
  m.bound(n) = {0, 1, 0};
  m.disp(n) = {0, vMax, 0};
  return m;
}

TEST(CantileverForce, FullStepsAcrossTheYieldKinkConvergeWithoutCutting) {
  for (int n : {10, 25}) {
    const Discrete d{n};
    const int steps = 25;
    const double vMax = 0.5;
    Model m = cantilever(n, vMax);
    Analysis an(m);
    an.setLoadFunction(1, ProportionalLoad::ramp());
    an.setDt(1.0 / steps);
    for (int s = 1; s <= steps; ++s) {
      ASSERT_TRUE(an.advance());
      IterationInfo info;
      int its = 0;
      bool converged = false;
      while (!converged && its < 20) {
        ASSERT_TRUE(an.iterate(true, true, info)) << "n = " << n << ", step " << s;
        ++its;
        converged = info.converged;
      }
      ASSERT_TRUE(converged) << "n = " << n << ", step " << s << " (v = " << vMax * s / steps << ")";
      Eigen::VectorXd r;
      ASSERT_TRUE(an.reactions(r));
      const double v = vMax * s / steps, P = r[3 * n + 1];
      EXPECT_NEAR(P, d.force(v), 1e-6 * d.pu()) << "n = " << n << ", v = " << v;
    }
    // One hinge, in the element at the clamp.
    int active = 0;
    for (int e = 0; e < n; ++e) {
      const HingeInfo h = dynamic_cast<const HingeCarrier&>(m.element(e)).hinge();
      if (h.active) {
        ++active;
        EXPECT_EQ(e, 0);
      }
    }
    EXPECT_EQ(active, 1) << "n = " << n;
  }
}

}  // namespace
}  // namespace c2d
