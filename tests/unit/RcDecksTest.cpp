// The RC decks against their closed forms: decks/rc/shear_critical_column.inp
// (a short column fails in shear at Vu(N)), decks/rc/column_capacity.inp
// (verification.md V20: a cantilever column under axial force reaches the base
// moment Mu(N)) and decks/rc/catenary.inp (V19: the catenary of a beam that lost
// its middle support, P = 2 T d / sqrt(L^2 + d^2) once the bars yield, until
// they fracture), and decks/rc/seven_story_removal.inp (the alternate path of
// a frame that lost an interior ground column: the same verdict and sags at
// three meshes).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "macro/DeckRunner.h"
#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

// A deck's run in a directory of its own, removed with it.
struct Ran {
  explicit Ran(const std::string& deck)
      : ran(testing::runSourceDeck(scratch, "rc/" + deck)), dir(ran.out), log(ran.log) {
    EXPECT_EQ(ran.outcome.exitCode, 0) << ran.outcome.message;
  }
  const testing::DeckTempDir scratch;
  const testing::DeckResult ran;
  const std::filesystem::path dir;
  std::string log;
};

Ran runRcDeck(const std::string& deck) { return Ran(deck); }

TEST(RcDecks, ColumnReachesTheSectionsUltimateMomentAtItsAxialForce) {
  const Ran r = runRcDeck("column_capacity.inp");
  // The hand calculations of tests/unit/RcSectionTest.cpp (the V20 section).
  const std::pair<const char*, double> cases[] = {
      {"Nx=0", 269.128}, {"Nx=-3000", 693.023}, {"Nx=500", 166.814}};
  for (const auto& [tag, mu] : cases) {
    const auto csv =
        testing::readCsv(r.dir / (std::string("column_capacity_") + tag + "_tplot.csv"));
    const auto m = csv.column("reac_1_3");
    ASSERT_FALSE(m.empty()) << tag;
    double peak = 0;
    for (double x : m) peak = std::max(peak, std::abs(x));
    // The law's tabulated Mu(N) interpolates the section's to 1e-5.
    EXPECT_NEAR(peak, mu, 2e-5 * mu) << tag;
  }
  EXPECT_EQ(r.log.find("max |M|/Mu 1.0000") != std::string::npos, true);
  EXPECT_EQ(r.log.find("past its capacity"), std::string::npos);  // macro/run/CapacityWatch.h
  // STRE,HINGe lists the base hinge's joint: softening at N = 0 and +500 kN,
  // failed at -3000 kN (the smallest failure jump).
  auto count = [&](const std::string& text) {
    std::size_t n = 0;
    for (std::size_t p = r.log.find(text); p != std::string::npos; p = r.log.find(text, p + 1)) ++n;
    return n;
  };
  EXPECT_EQ(count("  failed, end 1\n"), 1u);
  EXPECT_EQ(count("  active, end 1\n"), 2u);
  EXPECT_EQ(count("   1 hinges\n"), 3u);
}

// decks/rc/shear_critical_column.inp: a short column with sparse links fails
// in shear at Vu(N) (hand calculations of EC2 6.2.2 in the deck and in
// tests/unit/ShearResistanceTest.cpp), long before its ends reach Mu(N), and
// parts from its base: the base shear falls to zero.
TEST(RcDecks, ShearCriticalColumnFailsInShearAtVu) {
  const Ran r = runRcDeck("shear_critical_column.inp");
  const std::pair<const char*, double> cases[] = {{"Nx=0", 131.586}, {"Nx=-400", 184.086}};
  for (const auto& [tag, vu] : cases) {
    const auto csv =
        testing::readCsv(r.dir / (std::string("shear_critical_column_") + tag + "_tplot.csv"));
    const auto v = csv.column("reac_1_1");
    ASSERT_FALSE(v.empty()) << tag;
    double peak = 0;
    for (double x : v) peak = std::max(peak, std::abs(x));
    EXPECT_NEAR(peak, vu, 0.05 * vu) << tag;  // the band
    EXPECT_NEAR(peak, vu, 1e-5 * vu) << tag;  // the event's location: to round-off
    EXPECT_EQ(std::abs(v.back()), 0.0) << tag;  // parted: the pushover curve says so
  }
  auto count = [&](const std::string& text) {
    std::size_t n = 0;
    for (std::size_t p = r.log.find(text); p != std::string::npos; p = r.log.find(text, p + 1)) ++n;
    return n;
  };
  EXPECT_EQ(count("  shear  failure at t = "), 2u);
  EXPECT_NE(r.log.find("element 1 separates at node 1 (its end 1, new node 10), V = 1.840856e+02, "
                       "Vu(N) = 1.840856e+02 at N = -4.000000e+02"),
            std::string::npos);
  EXPECT_EQ(count("hinge  opened"), 0u);  // before Mu
  EXPECT_NE(r.log.find("max |M|/Mu 0.5647"), std::string::npos);
  // The summary counts them apart from the bars' fractures (one a run).
  EXPECT_EQ(count("1 member parted in shear"), 2u);
  EXPECT_EQ(count("parted by their bars"), 0u);
}

TEST(RcDecks, CatenaryOfTheBarsUntilTheyFracture) {
  const Ran r = runRcDeck("catenary.inp");
  const auto csv = testing::readCsv(r.dir / "catenary_tplot.csv");
  const auto t = csv.column("time"), v = csv.column("disp_7_2"), reac = csv.column("reac_7_2");
  ASSERT_EQ(t.size(), v.size());
  // Bars: 4 x 16 mm, fy = 500 MPa, fu = 540 MPa, eu = 0.05, Es As the tie's stiffness.
  const double L = 3, as = 4 * M_PI * 0.008 * 0.008, nt = as * 500e3, ntu = as * 540e3,
               esas = 200e6 * as, eu = 0.05, ht = (ntu - nt) / (eu - ntu / esas);
  int checked = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double d = -v[i];
    if (t[i] > 9.5 || d < 0.3) continue;  // the static push, the bars yielded and the hinges spent
    const double e = std::sqrt(1 + d * d / (L * L)) - 1;
    const double T = (nt + ht * e) / (1 + ht / esas);
    const double P = 2 * T * d / std::sqrt(L * L + d * d);
    EXPECT_NEAR(-reac[i], P, 2e-3 * P) << "d = " << d;
    ++checked;
  }
  EXPECT_GT(checked, 50);
  // The first fracture: at d_f = L sqrt((1 + eu)^2 - 1) (the push at 2 mm/s from
  // d = 0.95 m at t = 9.5 s).
  const std::string key = "bars   fractured at t = ";
  const std::size_t p = r.log.find(key);
  ASSERT_NE(p, std::string::npos);
  const double tf = std::stod(r.log.substr(p + key.size(), 14));
  const double df = 0.95 + 0.002 * (tf - 9.5);
  EXPECT_NEAR(df, L * std::sqrt((1 + eu) * (1 + eu) - 1), 2e-4);
  EXPECT_NE(r.log.find("energy error"), std::string::npos);
}

// Hinges at the element ends see the support moments at any mesh: the frame
// stays up at 2/4, 4/8 and 6/12 elements per column storey / beam bay, with
// the same hinges at the outer supports of the seven doubled spans and peak
// sags within 15 % of each other (2.6 % at the time step halved).
TEST(RcDecks, ColumnRemovalVerdictAndSagDoNotDependOnTheMesh) {
  const Ran r = runRcDeck("seven_story_removal.inp");
  const std::pair<int, int> meshes[] = {{2, 4}, {4, 8}, {6, 12}};
  std::vector<double> sags;
  for (const auto& [nc, nb] : meshes) {
    const std::string tag = "nc=" + std::to_string(nc) + "_nb=" + std::to_string(nb);
    const auto csv = testing::readCsv(r.dir / ("seven_story_removal_" + tag + "_tplot.csv"));
    // The node over the removed column at the first floor: 1 + (7 nc + 1) + nc.
    const auto v = csv.column("disp_" + std::to_string(2 + 8 * nc) + "_2");
    const auto kinetic = csv.column("kinetic"), t = csv.column("time");
    ASSERT_FALSE(v.empty()) << tag;
    ASSERT_NEAR(t.back(), 1.0, 1e-9) << tag;
    const double peak = -*std::min_element(v.begin(), v.end());
    // Up: the sag settles near its peak and the motion has died down.
    EXPECT_GT(-v.back(), 0.9 * peak) << tag;
    EXPECT_LT(-v.back(), peak) << tag;
    EXPECT_LT(kinetic.back(), 1.0) << tag;  // kJ, against 12 kJ at its peak after the removal
    sags.push_back(peak);
  }
  const double lo = *std::min_element(sags.begin(), sags.end()),
               hi = *std::max_element(sags.begin(), sags.end());
  EXPECT_GT(lo, 0.05);
  EXPECT_LT(hi, 1.15 * lo) << sags[0] << " " << sags[1] << " " << sags[2];
  // Every run opens the 14 negative hinges at the outer supports.
  std::size_t runs = 0;
  for (std::size_t p = r.log.find("summary: "); p != std::string::npos;
       p = r.log.find("summary: ", p + 1)) {
    const std::size_t h = r.log.find(" hinges", p);
    const std::size_t c = r.log.rfind(", ", h);
    EXPECT_GE(std::stoi(r.log.substr(c + 2, h - c - 2)), 14);
    ++runs;
  }
  EXPECT_EQ(runs, 3u);
}

// decks/rc/piece_impact.inp: a column piece struck by the ground fails as the
// air's loads would fail it. The rigid rod's estimate of element 1's shear in
// the first strike, 0.6875 cos 30 v sqrt(k m / 3.25), brackets Vu = 290 kN:
// 113 kN after a drop of 0.05 m (the piece bounces whole), 718 kN after 2 m
// (it fails in shear at its struck end within the strike, and breaks up).
TEST(RcDecks, APieceStruckBeyondItsShearCapacityFailsInTheStrike) {
  const Ran r = runRcDeck("piece_impact.inp");
  const double g = 9.81, m = 1.2, k = 1e5, vu = 290.2832;
  auto estimate = [&](double h) {
    return 0.6875 * std::cos(M_PI / 6) * std::sqrt(2 * g * h) * std::sqrt(k * m / 3.25);
  };
  ASSERT_LT(estimate(0.05), vu);
  ASSERT_GT(estimate(2.0), vu);
  // The low drop: element 1's shear stays below Vu and within the rod's
  // estimate; nothing fails in that run.
  const auto low = testing::readCsv(r.dir / "piece_impact_h=0.05_tplot.csv");
  double peak = 0;
  for (double v : low.column("stre_1_2")) peak = std::max(peak, std::abs(v));
  EXPECT_LT(peak, vu);
  EXPECT_GT(peak, 0.5 * estimate(0.05));
  EXPECT_LT(peak, 1.2 * estimate(0.05));
  const std::size_t second = r.log.find("run 2 of 2, outputs piece_impact_h=2");
  ASSERT_NE(second, std::string::npos);
  EXPECT_EQ(r.log.rfind("  shear  failure", second), std::string::npos);
  EXPECT_EQ(r.log.rfind("  hinge  opened", second), std::string::npos);
  // The high drop: the first shear failure is element 1's, within the strike
  // (the strike at sqrt(2 h / g); the contact lasts pi sqrt(m / (3.25 k))).
  const std::string key = "shear  failure at t = ";
  const std::size_t p = r.log.find(key);
  ASSERT_NE(p, std::string::npos);
  EXPECT_GT(p, second);  // in the high drop's run
  const double tf = std::stod(r.log.substr(p + key.size(), 14));
  const double strike = std::sqrt(2 * 2.0 / g), lasts = M_PI * std::sqrt(m / (3.25 * k));
  EXPECT_GT(tf, strike);
  EXPECT_LT(tf, strike + lasts);
  EXPECT_NE(r.log.substr(p, 80).find(": element 1 separates at node 2"), std::string::npos)
      << r.log.substr(p, 120);
  // The strike parts element 1; the pieces' own strikes part more (4 or 5).
  const std::size_t parted = r.log.find(" members parted in shear", second);
  ASSERT_NE(parted, std::string::npos);
  const std::size_t count = r.log.rfind(' ', parted - 1) + 1;
  EXPECT_GE(std::stoi(r.log.substr(count, parted - count)), 4);
}

}  // namespace
}  // namespace c2d
