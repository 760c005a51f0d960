// Arc-length path following through both limit points of the shallow two-bar
// arch (decks/pathfollowing/arch_arclength.inp): every converged point lies on
// the closed-form equilibrium path P(w) of the truss.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "macro/DeckRunner.h"
#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

using testing::readCsv;

TEST(ArcLength, ArchPathOnClosedForm) {
  const testing::DeckTempDir scratch;
  const testing::DeckResult ran =
      testing::runSourceDeck(scratch, "pathfollowing/arch_arclength.inp");
  ASSERT_EQ(ran.outcome.exitCode, 0) << ran.outcome.message;
  const auto rows = readCsv(ran.out / "arch_arclength_tplot.csv").rows;
  ASSERT_GE(rows.size(), 100u);
  const double a = 1, h = 0.1, EA = 1e6, L0 = std::hypot(a, h);
  double wMax = 0, pMax = -1e30, pMin = 1e30;
  for (const auto& r : rows) {
    const double w = -r[2], lambda = r[3];
    const double L = std::hypot(a, h - w);
    const double P = 2 * EA * (L0 - L) / L0 * (h - w) / L;
    EXPECT_NEAR(lambda, P, 1e-5 * 381.0) << "w = " << w;
    wMax = std::max(wMax, w);
    pMax = std::max(pMax, lambda);
    pMin = std::min(pMin, lambda);
  }
  // The path passes the limit load, the snap-back minimum and the zero at w = 2h.
  EXPECT_GT(pMax, 370.0);
  EXPECT_LT(pMin, -370.0);
  EXPECT_GT(wMax, 2 * h);
}

}  // namespace
}  // namespace c2d
