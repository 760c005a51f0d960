// Debris figures against the site (macro/output/Debris), the debris picture
// (macro/output/SvgDebris) and the peak ground force of a bar dropped on the ground.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "elements/ElementFactory.h"
#include "macro/DeckRunner.h"
#include "macro/batch/BatchRunner.h"
#include "macro/output/Debris.h"
#include "macro/output/SvgDebris.h"
#include "tests/unit/DeckTestSupport.h"
#include "tests/unit/ElementTestSupport.h"
#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

// Two elements of unit mass per length from (0,0) to (4,0), moved by (dx, 0).
Model twoBars(double dx, State& s) {
  Model m;
  m.materials()[1] = test::unitMassBarMaterial();
  for (int i = 0; i < 3; ++i) m.addNode(Vec2(2.0 * i, 0));
  for (int e = 0; e < 2; ++e)
    m.setElement(e, makeElement(m.materials().at(1), {e, e + 1}, m.coord(e), m.coord(e + 1)));
  s.resize(3);
  for (int n = 0; n < 3; ++n) s.u[3 * n] = dx;
  return m;
}

TEST(Debris, MassWhereItLies) {
  State s;
  Model m = twoBars(1.0, s);
  m.nodalMass(2) = {0.5, 0.5, 0};
  const auto pieces = massPieces(m, s);
  double total = 0;
  for (const MassPiece& p : pieces) total += p.mass;
  EXPECT_NEAR(total, 4.5, 1e-12);
  // Site [0, 4]: the second bar lies on [3, 5] (half outside), the nodal mass at 5.
  EXPECT_NEAR(massOutside(pieces, Site{0, 4}), 1.0 + 0.5, 1e-12);
  const auto h = massHistogram(pieces, 1.0, 1.0, 4);  // bins [1,2) ... [4,5]
  ASSERT_EQ(h.size(), 4u);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(h[k], 1.0, 1e-12);
  EXPECT_NEAR(h[3], 1.5, 1e-12);  // the point mass at the last bin's edge counts in it

  m.site() = Site{0, 4};
  const DebrisFigures d = debrisFigures(m, s);
  EXPECT_DOUBLE_EQ(d.footprintMin, 0);
  EXPECT_DOUBLE_EQ(d.footprintMax, 4);
  EXPECT_DOUBLE_EQ(d.left, 0);
  EXPECT_DOUBLE_EQ(d.right, 1);
  EXPECT_TRUE(d.outside());
  EXPECT_EQ(d.siteStatus(), "outside");
  EXPECT_NEAR(d.outsideMass, 1.5, 1e-12);

  m.site().reset();
  const DebrisFigures none = debrisFigures(m, s);
  EXPECT_EQ(none.siteStatus(), "none");
  EXPECT_EQ(none.outsideMass, 0);
  EXPECT_NE(debrisCsvRow(none).find(",none,,,"), std::string::npos) << debrisCsvRow(none);
  EXPECT_NE(debrisLogLines(none).find("no site given"), std::string::npos);
}

// The robust figures by hand: two unit-mass-per-length bars on [0, 2] and
// [2, 4] moved by 1 (pieces on [1, 3], [3, 5]) and a point mass 0.5 at x = 5.
// Total 4.5; mass below x: x - 1 on [1, 5), 4.5 at 5.
//   5 % (0.225) lies below x = 1.225, 95 % (4.275) below x = 5 (the point mass);
//   centroid (2 * 2 + 2 * 4 + 0.5 * 5) / 4.5 = 14.5 / 4.5, at the start 10 / 4.5
//   (bars at 1 and 3, the point mass at 4): shift 1.
TEST(Debris, RobustFiguresByHand) {
  State s;
  Model m = twoBars(1.0, s);
  m.nodalMass(2) = {0.5, 0.5, 0};
  const auto pieces = massPieces(m, s);
  EXPECT_NEAR(massQuantile(pieces, 0.05), 1.225, 1e-12);
  EXPECT_NEAR(massQuantile(pieces, 0.5), 1 + 2.25, 1e-12);
  EXPECT_NEAR(massQuantile(pieces, 0.95), 5, 1e-12);
  EXPECT_NEAR(massQuantile(pieces, 0.85), 1 + 0.85 * 4.5, 1e-12);
  const DebrisFigures d = debrisFigures(m, s);
  EXPECT_NEAR(d.centroid, 14.5 / 4.5, 1e-12);
  EXPECT_NEAR(d.centroidShift, 1, 1e-12);
  EXPECT_NEAR(d.left95, 0, 1e-12);
  EXPECT_NEAR(d.right95, 1, 1e-12);
  // One piece: both bars and the nodal mass.
  EXPECT_NEAR(d.leftPieceMass, 4.5, 1e-12);
  EXPECT_NEAR(d.rightPieceMass, 4.5, 1e-12);
  ASSERT_EQ(d.cover.size(), 1u);
  EXPECT_NEAR(d.cover[0].first, 1, 1e-12);
  EXPECT_NEAR(d.cover[0].second, 5, 1e-12);

  // The union of separate pieces.
  const auto cover = massCover({{9, 11, 1}, {0, 2, 1}, {1, 3, 1}, {5, 5, 1}});
  ASSERT_EQ(cover.size(), 3u);
  EXPECT_EQ(cover[0], std::make_pair(0.0, 3.0));
  EXPECT_EQ(cover[1], std::make_pair(5.0, 5.0));
  EXPECT_EQ(cover[2], std::make_pair(9.0, 11.0));

  // The first bar blasted away: the second (mass 2 + 0.5) is the piece at both
  // ends; the first bar's free node is no longer debris.
  s.u[3 * 1] = 8;
  s.u[3 * 2] = 7;
  m.removeElement(0);
  const DebrisFigures alone = debrisFigures(m, s);
  EXPECT_NEAR(alone.rightPieceMass, 2.5, 1e-12);
  EXPECT_NEAR(alone.leftPieceMass, 2.5, 1e-12);
  EXPECT_NEAR(alone.centroid, (2 * 10.5 + 0.5 * 11) / 2.5, 1e-12);
  ASSERT_EQ(alone.cover.size(), 1u);
  EXPECT_NEAR(alone.cover[0].first, 10, 1e-12);
}

// A run not at rest: the kinetic energy ratio against TIME,REST's.
TEST(Debris, AtRestAgainstTheRatio) {
  DebrisFigures d;
  d.kineticRatio = 2e-2;
  EXPECT_FALSE(d.atRest());
  EXPECT_NE(debrisLogLines(d).find("STILL MOVING"), std::string::npos);
  EXPECT_NE(debrisCsvRow(d).find(",no,"), std::string::npos);
  d.kineticRatio = 1e-6;
  EXPECT_TRUE(d.atRest());
  EXPECT_NE(debrisCsvRow(d).find(",yes,"), std::string::npos);
  // The row has as many cells as the header.
  const std::string h = debrisCsvHeader(), r = debrisCsvRow(d);
  EXPECT_EQ(std::count(h.begin(), h.end(), ','), std::count(r.begin(), r.end(), ','));
}

TEST(Debris, PictureShowsFootprintSiteAndHistogram) {
  State s;
  Model m = twoBars(-3.0, s);
  m.ground() = Ground{0, 1e4, 0};
  m.site() = Site{-1, 6};
  const DebrisFigures d = debrisFigures(m, s);
  EXPECT_DOUBLE_EQ(d.left, 3);
  const std::string svg = debrisSvg(m, s, d, "two bars", 10);
  EXPECT_NE(svg.find("class=\"footprint\""), std::string::npos);
  EXPECT_NE(svg.find("class=\"ground\""), std::string::npos);
  std::size_t sites = 0;
  for (std::size_t p = svg.find("class=\"site\""); p != std::string::npos;
       p = svg.find("class=\"site\"", p + 1))
    ++sites;
  EXPECT_EQ(sites, 2u);
  std::size_t bars = 0;
  const std::size_t hist = svg.find("class=\"histogram\"");
  ASSERT_NE(hist, std::string::npos);
  for (std::size_t p = svg.find("<rect", hist);
       p != std::string::npos && p < svg.find("</g>", hist); p = svg.find("<rect", p + 1))
    ++bars;
  // The bars lie on [-3, 1]: 4 of the 10 bins over [-3.5, 6.5] (x range with 5 % margins).
  EXPECT_GE(bars, 4u);
  EXPECT_LE(bars, 6u);
  EXPECT_NE(svg.find("OUTSIDE the site"), std::string::npos);
  // Lines are strokes only: a path without fill="none" is filled black (the
  // axis drew a black triangle over the histogram).
  for (std::size_t p = svg.find("<path"); p != std::string::npos; p = svg.find("<path", p + 1))
    EXPECT_NE(svg.substr(p, svg.find('>', p) - p).find("fill="), std::string::npos)
        << svg.substr(p, svg.find('>', p) - p);
  m.site().reset();
  const std::string plain = debrisSvg(m, s, debrisFigures(m, s), "two bars", 10);
  EXPECT_EQ(plain.find("class=\"site\""), std::string::npos);
}

// The bar of decks/collapse/bar_drop.inp: the largest total ground force is the
// penalty force at the deepest penetration, K (m g/K + sqrt((m g/K)^2 + m v0^2/K)),
// sampled at the steps (dt = 5e-4, omega dt = 0.08).
TEST(Debris, BarDropPeakGroundForce) {
  testing::DeckTempDir dir;
  const testing::DeckResult ran = testing::runSourceDeck(dir, "collapse/bar_drop.inp");
  const DeckOutcome& o = ran.outcome;
  ASSERT_EQ(o.exitCode, 0) << o.message;
  EXPECT_EQ(o.total.debrisRuns, 1);
  EXPECT_EQ(o.total.outsideRuns, 0);
  std::ifstream in(ran.out / "bar_drop_debris.csv");
  std::string header, row;
  ASSERT_TRUE(std::getline(in, header));
  ASSERT_TRUE(std::getline(in, row));
  EXPECT_EQ(header, debrisCsvHeader());
  std::vector<std::string> cells;
  std::stringstream ss(row);
  for (std::string c; std::getline(ss, c, ',');) cells.push_back(c);
  // The site's verdict, flyrock and risk columns included; the last (risk_confidence)
  // is empty without a site, and getline drops a trailing empty cell.
  ASSERT_EQ(cells.size(), 31u) << row;
  const double L = 2, n = 4, h0 = 0.05, k = 1e4, g = 9.81, m = L;
  const double K = (n + 1) * k, v0 = std::sqrt(2 * g * h0);
  const double pen = m * g / K + std::sqrt(std::pow(m * g / K, 2) + m * v0 * v0 / K);
  EXPECT_NEAR(std::stod(cells[8]), K * pen, 5e-3 * K * pen);
  EXPECT_EQ(cells[5], "none");
  EXPECT_NEAR(std::stod(cells[3]), m, 1e-12);  // total mass rho A L
  // The peak comes a quarter contact period after the impact at sqrt(2 h0/g).
  const double omega = std::sqrt(K / m);
  EXPECT_NEAR(std::stod(cells[9]), std::sqrt(2 * h0 / g) + 0.5 * 3.14159265 / omega, 3e-3);
  // The deepest node went as deep as that penetration, at the same time.
  EXPECT_NEAR(std::stod(cells[10]), pen, 5e-3 * pen);
  EXPECT_NEAR(std::stod(cells[11]), std::stod(cells[9]), 1e-3);
  EXPECT_EQ(o.total.sunk, 0);
}

// The same bar on a ground a hundred times softer sinks 0.113 m, deeper than
// half its section (sqrt(3 I / A) = 0.055 m): the log's debris line says it
// is buried, and the run warns.
TEST(Debris, ANodeDeeperThanHalfItsSectionIsBuriedAndWarned) {
  testing::DeckTempDir dir;
  const std::filesystem::path deck = dir.path() / "soft_ground.inp";
  std::ofstream(deck) << "PARAmeter\n  L = 2\n  n = 4\n  h0 = 0.05\n  k = 1e2\n  g = 9.81\n"
                         "  e = 1\n\nINCLude,"
                      << C2D_SOURCE_DIR << "/decks/collapse/bar_drop.inc\n\nSTOP\n";
  const testing::DeckResult ran = testing::runDeckFile(dir, deck.string());
  const DeckOutcome& o = ran.outcome;
  ASSERT_EQ(o.exitCode, 0) << o.message;
  EXPECT_EQ(o.total.sunk, 1);
  const std::string& text = ran.log;
  const double L = 2, n = 4, h0 = 0.05, k = 1e2, g = 9.81, m = L;
  const double K = (n + 1) * k, v0 = std::sqrt(2 * g * h0);
  const double pen = m * g / K + std::sqrt(std::pow(m * g / K, 2) + m * v0 * v0 / K);
  EXPECT_NEAR(pen, 0.113, 1e-3);
  const std::size_t at = text.find("debris: deepest in the ground ");
  ASSERT_NE(at, std::string::npos) << text;
  EXPECT_NEAR(std::stod(text.substr(at + 30)), pen, 5e-3 * pen);
  EXPECT_NE(text.find("half its members' section depth 5.4772e-02 m: BURIED", at),
            std::string::npos)
      << text.substr(at, 200);
  EXPECT_NE(text.find("warning: in this run a node went deeper into the ground than half"),
            std::string::npos);
}

// A run whose debris leaves the site says so in its summary line and in the
// batch table; a deck without ground contact has no debris figures.
TEST(Debris, OutsideTheSiteInSummaryAndBatchTable) {
  testing::DeckTempDir dir;
  BatchOptions o;
  o.deck.outDir = dir.path();
  const SolutionCommands commands;
  std::ostringstream out;
  const std::string decks = std::string(C2D_SOURCE_DIR) + "/decks/";
  const auto results = runBatch(
      {decks + "output/debris_site.inp", decks + "loads/floor_load_beam.inp"}, o, deckCalls(commands), out);
  ASSERT_EQ(results.size(), 2u);
  EXPECT_TRUE(results[0].ok()) << results[0].output;
  EXPECT_EQ(results[0].debrisRuns, 1);
  EXPECT_EQ(results[0].outsideRuns, 1);
  EXPECT_NE(results[0].output.find("debris OUTSIDE the site"), std::string::npos)
      << results[0].output;
  EXPECT_EQ(results[1].debrisRuns, 0);
  std::ostringstream table;
  printBatchTable(table, results);
  const std::string t = table.str();
  EXPECT_NE(t.find("debris"), std::string::npos) << t;
  EXPECT_NE(t.find("OUTSIDE"), std::string::npos) << t;
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "debris_site_debris.csv"));
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "debris_site_debris.svg"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "floor_load_beam_debris.csv"));
}

}  // namespace
}  // namespace c2d
