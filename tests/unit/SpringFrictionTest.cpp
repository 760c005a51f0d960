// The friction's stick element (core/contact/SpringFriction): a spring k and
// a dashpot c in parallel, in series with Coulomb's slider at mu N. Under the
// mid-point scheme its work is the spring's change plus what the dashpot and
// the slider dissipate, exactly; its stretch never leaves mu N / k, so over
// any run of steps it gives back at most what it stored, and never more than
// (mu N)^2 / (2 k); its force is bounded by mu N and its derivatives are exact
// (central differences). A sudden slip meets mu N at once through the dashpot.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/contact/SpringFriction.h"

namespace c2d {
namespace {

constexpr double k = 2e5, mu = 0.5, m = 0.45;  // the landing bar's node (kN/m, t)

TEST(SpringFriction, WorkIsStoredPlusDissipatedAndTheStretchStaysWithinItsReach) {
  const double N = 3000, L = mu * N / k;
  for (const double c : {0.0, frictionStickDamping(k, m), 50 * frictionStickDamping(k, m)})
    for (const double h : {1e-4, 1e-3, 1e-2})
      for (const bool midPoint : {true, false})
        for (double e : {-3 * L, -L, -0.4 * L, 0.0, 0.8 * L, 2 * L})
          for (double dx : {-0.3, -2 * L, -0.3 * L, -1e-9, 0.0, 2e-9, 0.2 * L, 1.5 * L, 0.2}) {
            const double xn = 0.1, x = xn + dx;
            const SpringFrictionForce f = springFriction(k, c, mu, N, xn - e, xn, x, h, midPoint);
            EXPECT_LE(std::abs(f.force), mu * N * (1 + 1e-12));
            EXPECT_LE(std::abs(x - f.anchor), L * (1 + 1e-12));
            EXPECT_GE(f.slipped, 0.0);
            if (!midPoint) continue;
            EXPECT_NEAR(-f.force * dx,
                        springFrictionEnergy(k, x - f.anchor) - springFrictionEnergy(k, e) +
                            f.slipped,
                        1e-12 * mu * N * (L + std::abs(dx) + std::abs(e)))
                << "c " << c << " h " << h << " e " << e << " dx " << dx;
          }
}

TEST(SpringFriction, DerivativesMatchCentralDifferences) {
  const double N = 3000, L = mu * N / k, c = frictionStickDamping(k, m);
  for (const bool midPoint : {true, false})
    for (const double h : {1e-3, 1e-2})
      for (double e : {-2 * L, -0.6 * L, 0.3 * L, 1.5 * L})
        for (double dx : {-1.7 * L, -0.4 * L, -0.05 * L, 0.07 * L, 0.55 * L, 2.3 * L, 0.05}) {
          const double a = -e, x = dx;
          const SpringFrictionForce f = springFriction(k, c, mu, N, a, 0.0, x, h, midPoint);
          const double sx = 1e-7 * L, sN = 1e-6 * N;
          const double fx = (springFriction(k, c, mu, N, a, 0.0, x + sx, h, midPoint).force -
                             springFriction(k, c, mu, N, a, 0.0, x - sx, h, midPoint).force) /
                            (2 * sx);
          const double fN = (springFriction(k, c, mu, N + sN, a, 0.0, x, h, midPoint).force -
                             springFriction(k, c, mu, N - sN, a, 0.0, x, h, midPoint).force) /
                            (2 * sN);
          EXPECT_NEAR(f.dx, fx, 1e-6 * (k + c / h)) << "e " << e << " dx " << dx;
          EXPECT_NEAR(f.dN, fN, 1e-6 * mu) << "e " << e << " dx " << dx;
        }
}

// Random walks of the point and of N (the contact loading and unloading):
// over every run of steps the work friction does on the point is at most the
// energy its spring held at the run's start, which is at most (mu N)^2 / (2 k)
// for the N of the step that left it.
TEST(SpringFriction, TheSpringNeverGivesBackMoreThanItsReachCanStore) {
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (const double c : {0.0, frictionStickDamping(k, m), 20 * frictionStickDamping(k, m)})
    for (const double h : {1e-4, 1e-3, 1e-2}) {
      double x = 0, a = 0, N = 2000;
      std::vector<double> stored{0.0}, given{0.0};  // at each step's end; work on the point since
      double worst = 0;
      for (int i = 0; i < 400; ++i) {
        N = std::max(0.0, N * (1 + 0.5 * unit(gen)) + 200 * unit(gen));
        const double L = mu * N / k;
        const double dx = (i % 7 == 0 ? 5 : 1) * L * unit(gen);
        const SpringFrictionForce f = springFriction(k, c, mu, N, a, x, x + dx, h, true);
        x += dx;
        a = f.anchor;
        const double E = springFrictionEnergy(k, x - a);
        EXPECT_LE(E, 0.5 * mu * N * mu * N / k * (1 + 1e-12) + 1e-300);
        given.push_back(given.back() + f.force * dx);
        stored.push_back(E);
        // The largest return over any run of steps ending here.
        for (std::size_t j = 0; j + 1 < given.size(); ++j)
          worst = std::max(worst, given.back() - given[j] - stored[j]);
      }
      EXPECT_LE(worst, 1e-9) << "c " << c << " h " << h;
    }
}

// A point sliding at v onto a loaded contact meets mu N at once (c v >= mu N
// here), whatever the step; the spring alone meets k v h.
TEST(SpringFriction, ASuddenSlipMeetsMuNAtOnce) {
  const double N = 3000, v = 3.96, c = frictionStickDamping(k, m);
  ASSERT_GT(c * v, 0.5 * mu * N);
  for (const double h : {1e-4, 1e-3, 1e-2}) {
    const SpringFrictionForce f = springFriction(k, c, mu, N, 0.0, 0.0, v * h, h, true);
    const SpringFrictionForce spring = springFriction(k, 0.0, mu, N, 0.0, 0.0, v * h, h, true);
    EXPECT_LT(f.force, -std::min(mu * N, 0.5 * c * v)) << h;
    if (h < 1e-3) {
      EXPECT_GT(spring.force, -0.1 * mu * N) << h;
    }
  }
}

}  // namespace
}  // namespace c2d
