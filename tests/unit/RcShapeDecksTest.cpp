// The decks of the SECTion shapes and of V21: decks/rc/tee_beam.inp (a
// T-beam cantilever reaches Mu+ pushed one way and the smaller Mu- the other),
// decks/rc/circular_column.inp (a circular column reaches Mu(N) at two axial
// forces), decks/rc/toppling_rod.inp (verification.md V21: the toppling
// rod's largest moment at L/3, mu g L^2 sin(theta)/27 within 3 %) and
// decks/rc/chimney_felling.inp (the felled chimney breaks in the air within
// 0.25-0.5 of its height).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

#include "materials/RcSection.h"
#include "tests/unit/RcTestSupport.h"
#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

using test::c30b500;

using testing::DeckResult;
using testing::DeckTempDir;

const double kPi = std::acos(-1.0);

DeckResult runRcDeck(const DeckTempDir& dir, const std::string& name) {
  DeckResult r = testing::runSourceDeck(dir, "rc/" + name);
  EXPECT_EQ(r.outcome.exitCode, 0) << r.outcome.message << r.console;
  return r;
}

double peakMagnitude(const std::filesystem::path& csv, const std::string& column) {
  double peak = 0;
  for (double x : testing::readCsv(csv).column(column)) peak = std::max(peak, std::abs(x));
  return peak;
}

TEST(RcShapeDecks, TeeBeamReachesTheLargerMuWithItsFlangeCompressed) {
  DeckTempDir dir;
  const DeckResult r = runRcDeck(dir, "tee_beam.inp");
  const RcSection s(test::teeBeam());
  const double up = peakMagnitude(r.out / "tee_beam_dir=1_tplot.csv", "reac_1_3");
  const double down = peakMagnitude(r.out / "tee_beam_dir=-1_tplot.csv", "reac_1_3");
  EXPECT_NEAR(up, s.ultimate(0, 1).M, 2e-5 * up);
  EXPECT_NEAR(down, s.ultimate(0, -1).M, 2e-5 * down);
  EXPECT_GT(up, 1.4 * down);
  EXPECT_NE(r.log.find("max |M|/Mu 1.0000"), std::string::npos);
}

TEST(RcShapeDecks, CircularColumnReachesMuOfItsAxialForce) {
  DeckTempDir dir;
  const DeckResult r = runRcDeck(dir, "circular_column.inp");
  RcSectionData d = c30b500();
  d.shape = SectionShapeKind::Circle;
  d.b = d.h = 0.6;
  for (int i = 0; i < 12; ++i)
    d.bars.push_back({0.3 - 0.24 * std::cos(2 * kPi * i / 12), kPi * 1e-4});
  const RcSection s(d);
  for (double n : {0.0, -2000.0}) {
    const std::string tag = n == 0 ? "Nx=0" : "Nx=-2000";
    const double peak =
        peakMagnitude(r.out / ("circular_column_" + tag + "_tplot.csv"), "reac_1_3");
    // The law's Mu(N) is the section's at N = 0 (a node of its table) and
    // interpolated between nodes elsewhere (3e-4 at -2000 kN).
    EXPECT_NEAR(peak, s.ultimate(n, 1).M, (n == 0 ? 2e-5 : 5e-4) * peak) << tag;
  }
  EXPECT_GT(s.ultimate(-2000, 1).M, 1.5 * s.ultimate(0, 1).M);
}

// V21: from the tip's position the angle theta; per recorded row the largest
// element moment and its neighbours locate the peak (a parabola through the
// three midpoints), against x = L/3 and mu g L^2 sin(theta)/27.
TEST(RcShapeDecks, TopplingRodCarriesItsLargestMomentAtAThirdOfItsLength) {
  DeckTempDir dir;
  const DeckResult r = runRcDeck(dir, "toppling_rod.inp");
  const testing::Csv csv = testing::readCsv(r.out / "toppling_rod_tplot.csv");
  constexpr int kElements = 30;
  const double L = 10, mu = 0.25, g = 9.81, th0 = 10 * kPi / 180;
  const auto x = csv.column("disp_31_1"), y = csv.column("disp_31_2");
  std::vector<std::vector<double>> m;
  for (int e = 1; e <= kElements; ++e) m.push_back(csv.column("stre_" + std::to_string(e) + "_3"));
  int checked = 0;
  double worst = 0, lastTheta = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double theta = std::atan2(L * std::sin(th0) + x[i], L * std::cos(th0) + y[i]);
    lastTheta = theta;
    if (theta < 15 * kPi / 180) continue;  // after the release's vibration has died out
    int k = 1;
    for (int e = 1; e + 1 < kElements; ++e)
      if (std::abs(m[e][i]) > std::abs(m[k][i])) k = e;
    const double a = std::abs(m[k - 1][i]), b = std::abs(m[k][i]), c = std::abs(m[k + 1][i]);
    const double shift = 0.5 * (a - c) / (a - 2 * b + c);
    const double peak = b - 0.25 * (a - c) * shift, at = (k + 0.5 + shift) / kElements * L;
    const double closed = mu * g * L * L * std::sin(theta) / 27;
    EXPECT_NEAR(at, L / 3, 0.02 * L) << "theta " << theta;
    EXPECT_NEAR(peak, closed, 0.03 * closed) << "theta " << theta;
    worst = std::max(worst, std::abs(peak / closed - 1));
    ++checked;
  }
  EXPECT_GT(checked, 20);
  EXPECT_GT(lastTheta, 60 * kPi / 180);
  EXPECT_LT(worst, 0.01);  // measured 0.7 %
}

// The first hinge of the felled chimney: its node's height along the shaft
// (node k at 0.5 + (k - 1) m; the shaft's 100 m from node 1).
TEST(RcShapeDecks, ChimneyBreaksInTheAirBetweenAQuarterAndHalfItsHeight) {
  DeckTempDir dir;
  const DeckResult r = runRcDeck(dir, "chimney_felling.inp");
  const std::regex opened(
      R"(hinge  opened at t = ([0-9.e+-]+): element (\d+) end \d \(node (\d+),.*at N = ([0-9.e+-]+))");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.log, m, opened)) << r.log.substr(0, 2000);
  const double s = std::stod(m[3].str()) - 1, H = 100;
  EXPECT_GE(s / H, 0.25);
  EXPECT_LE(s / H, 0.5);
  EXPECT_LT(std::stod(m[4].str()), 0.0);  // under compression, early in the fall
  EXPECT_NE(r.log.find("max |M|/Mu 1.0000"), std::string::npos);
}

}  // namespace
}  // namespace c2d
