// The site's protected zones and flying fragments (core/DebrisZones), their
// statistics over a table of runs (macro/studies/ZoneStatistics) and the exact
// binomial bound of the sample-size rule (macro/studies/BinomialBound), by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/Debris.h"
#include "core/DebrisZones.h"
#include "elements/ElementFactory.h"
#include "macro/DeckRunner.h"
#include "macro/studies/BinomialBound.h"
#include "macro/studies/EnsemblePicture.h"
#include "macro/studies/PlanStatistics.h"
#include "macro/studies/Statistics.h"
#include "macro/studies/ZoneStatistics.h"
#include "tests/unit/ElementTestSupport.h"

namespace c2d {
namespace {

// Two bars of unit mass per length on [0, 2] and [2, 4] at y = 0 (one piece
// of 4 t), and a loose bar of 0.5 t from (3.5, 1) to (4, 1), thrown by 6.5 m
// to [10, 10.5]. Ground y = 0.
Model withFragment(State& s) {
  Model m;
  m.materials()[1] = test::unitMassBarMaterial();
  for (int i = 0; i < 3; ++i) m.addNode(Vec2(2.0 * i, 0));
  m.addNode(Vec2(3.5, 1));
  m.addNode(Vec2(4, 1));
  for (int e = 0; e < 2; ++e)
    m.setElement(e, makeElement(m.materials().at(1), {e, e + 1}, m.coord(e), m.coord(e + 1)));
  m.setElement(2, makeElement(m.materials().at(1), {3, 4}, m.coord(3), m.coord(4)));
  m.ground() = Ground{0, 1e6};
  s.resize(5);
  s.u[3 * 3] = s.u[3 * 4] = 6.5;
  return m;
}

const ZoneFigures& zone(const DebrisFigures& d, const std::string& name) {
  for (const ZoneFigures& z : d.zones)
    if (z.name == name) return z;
  throw std::runtime_error("no zone " + name);
}

TEST(SiteZones, SegmentShareInAZone) {
  EXPECT_DOUBLE_EQ(shareInZone(Vec2(0, 0), Vec2(4, 0), 1, 3, -kUnbounded), 0.5);
  EXPECT_DOUBLE_EQ(shareInZone(Vec2(0, 0), Vec2(4, 0), 1, 3, 0.5), 0.0);
  EXPECT_DOUBLE_EQ(shareInZone(Vec2(0, 0), Vec2(0, 4), -1, 1, 1), 0.75);  // above y = 1
  EXPECT_DOUBLE_EQ(shareInZone(Vec2(0, 0), Vec2(4, 4), 2, kUnbounded, 3), 0.25);
  EXPECT_DOUBLE_EQ(shareInZone(Vec2(2, 2), Vec2(2, 2), 1, 3, 0), 1.0);  // a point inside
  EXPECT_DOUBLE_EQ(shareInZone(Vec2(5, 2), Vec2(5, 2), 1, 3, 0), 0.0);
}

// The split: with FLYRock 1 t the loose 0.5 t bar is a fragment; the bed's
// figures leave it out, the zones count it apart.
TEST(SiteZones, FlyrockApartFromTheBed) {
  State s;
  Model m = withFragment(s);
  Site site{-1, 6};
  site.flyrockMass = 1.0;
  site.objects = {{"road", 8, 12, 0, 0},
                  {"canopy", 1, 3, 0.5, 0},
                  {"pile", 1, 3, 0, 0},
                  {"yard", 1, 3, 0, 2.5}};
  m.site() = site;
  const DebrisFigures d = debrisFigures(m, s);
  EXPECT_DOUBLE_EQ(d.totalMass, 4.5);
  EXPECT_DOUBLE_EQ(d.flyrockLimit, 1.0);
  EXPECT_EQ(d.flyrockCount, 1);
  EXPECT_DOUBLE_EQ(d.flyrockMass, 0.5);
  // The bed: [0, 4], inside the site, its centroid at 2 (it did not move).
  EXPECT_DOUBLE_EQ(d.xmax, 4);
  EXPECT_DOUBLE_EQ(d.right, 0);
  EXPECT_FALSE(d.outside());
  EXPECT_DOUBLE_EQ(d.outsideMass, 0);
  EXPECT_NEAR(d.centroid, 2, 1e-12);
  EXPECT_NEAR(d.centroidShift, 0, 1e-12);
  ASSERT_EQ(d.zones.size(), 6u);  // left, right, then the deck's four
  EXPECT_EQ(d.zones[0].name, "left");
  EXPECT_EQ(d.zones[1].name, "right");
  for (const char* z : {"right", "road"}) {
    EXPECT_DOUBLE_EQ(zone(d, z).mass, 0) << z;
    EXPECT_FALSE(zone(d, z).hit) << z;
    EXPECT_EQ(zone(d, z).flyrockCount, 1) << z;
    EXPECT_DOUBLE_EQ(zone(d, z).flyrockMass, 0.5) << z;
    EXPECT_DOUBLE_EQ(zone(d, z).heaviest, 0.5) << z;
  }
  EXPECT_EQ(zone(d, "left").flyrockCount, 0);
  EXPECT_DOUBLE_EQ(zone(d, "left").heaviest, 0);
  EXPECT_DOUBLE_EQ(zone(d, "canopy").mass, 0);  // the bed lies below 0.5 m
  EXPECT_DOUBLE_EQ(zone(d, "pile").mass, 2);    // half of each bar
  EXPECT_TRUE(zone(d, "pile").hit);
  EXPECT_DOUBLE_EQ(zone(d, "pile").heaviest, 4);
  EXPECT_FALSE(zone(d, "yard").hit);  // 2 t where 2.5 t may land
  const std::string row = debrisCsvRow(d, zoneNames(d));
  EXPECT_NE(row.find(",1.000000e+00,1,5.000000e-01,"), std::string::npos) << row;

  // With a limit below the bar's mass it is part of the bed: the bed reaches 10.5.
  m.site()->flyrockMass = 0.1;
  const DebrisFigures all = debrisFigures(m, s);
  EXPECT_EQ(all.flyrockCount, 0);
  EXPECT_DOUBLE_EQ(all.xmax, 10.5);
  EXPECT_TRUE(all.outside());
  EXPECT_DOUBLE_EQ(all.outsideMass, 0.5);
  EXPECT_TRUE(zone(all, "right").hit);
  EXPECT_DOUBLE_EQ(zone(all, "right").mass, 0.5);
  // The default limit, 1 % of 4.5 t, also keeps the 0.5 t bar in the bed.
  m.site()->flyrockMass = -1;
  EXPECT_DOUBLE_EQ(debrisFigures(m, s).flyrockLimit, 0.045);
  // A felling to the right: the right side receives the debris and is no zone.
  m.site()->dir = FallDirection::Right;
  EXPECT_EQ(zoneNames(m.site()), (std::vector<std::string>{"left", "road", "canopy", "pile", "yard"}));
}

// 0 of n at 95 %: the exact bound 1 - 0.05^(1/n) falls below 1 % at n = 299;
// Wilson's interval (z = 1.96), z^2/(n + z^2) < 0.01, only at n = 381.
TEST(SiteZones, SampleSizeRuleByHand) {
  EXPECT_NEAR(clopperPearsonUpper(0, 20, 0.95), 1 - std::pow(0.05, 1.0 / 20), 1e-14);
  EXPECT_NEAR(clopperPearsonUpper(0, 20, 0.95), 0.13911, 1e-5);
  EXPECT_NEAR(wilsonInterval(0, 20).second, 3.8416 / 23.8416, 1e-12);  // 0.161
  EXPECT_LT(clopperPearsonUpper(0, 299, 0.95), 0.01);
  EXPECT_GE(clopperPearsonUpper(0, 298, 0.95), 0.01);
  EXPECT_EQ(runsToShowBelow(0, 20, 0.01, 0.95), 299);
  EXPECT_EQ(runsToShowBelow(0, 400, 0.01, 0.95), 400);  // shown already
  int wilson = 1;
  while (wilsonInterval(0, wilson).second >= 0.01) ++wilson;
  EXPECT_EQ(wilson, 381);
  // 1 of 10: the one-sided 95 % bound solves P(X <= 1; 10, p) = 0.05, p = 0.3942.
  const double p = clopperPearsonUpper(1, 10, 0.95);
  EXPECT_NEAR(p, 0.39416, 1e-4);
  EXPECT_NEAR(std::pow(1 - p, 10) + 10 * p * std::pow(1 - p, 9), 0.05, 1e-9);
  EXPECT_DOUBLE_EQ(clopperPearsonUpper(3, 3, 0.95), 1.0);
  // One hit: the runs with no more hits that bring the bound below 1 %:
  // P(X <= 1; n, 0.01) = 0.05 first at n = 473.
  const long long n1 = runsToShowBelow(1, 20, 0.01, 0.95);
  EXPECT_LT(clopperPearsonUpper(1, static_cast<int>(n1), 0.95), 0.01);
  EXPECT_GE(clopperPearsonUpper(1, static_cast<int>(n1 - 1), 0.95), 0.01);
  EXPECT_EQ(n1, 473);
}

EnsembleRun run(std::map<std::string, double> figures) {
  EnsembleRun r;
  r.ok = r.debris = true;
  r.site = "inside";
  r.figures = std::move(figures);
  return r;
}

// Five runs, zones left (a protected side; the right receives) and wall.
TEST(SiteZones, ZoneCountsAndWilsonByHand) {
  std::vector<EnsembleRun> runs = {
      run({{"mass_left", 0}, {"hit_left", 0}, {"mass_wall", 2}, {"hit_wall", 1},
           {"flyrock_count_wall", 0}, {"left95", 1}, {"right95", 10}}),
      run({{"mass_left", 0.5}, {"hit_left", 1}, {"mass_wall", 0}, {"hit_wall", 0},
           {"flyrock_count_wall", 2}, {"left95", 3}, {"right95", 12}}),
      run({{"mass_left", 0}, {"hit_left", 0}, {"mass_wall", 0}, {"hit_wall", 0},
           {"left95", 0.5}, {"right95", 11}}),
      run({{"mass_left", 0}, {"hit_left", 0}, {"mass_wall", 0}, {"hit_wall", 0},
           {"left95", 0}, {"right95", 9}}),
      run({{"mass_left", 0}, {"hit_left", 0}, {"mass_wall", 1}, {"hit_wall", 1},
           {"left95", 0}, {"right95", 13}, {"risk_level", 0.05}, {"risk_confidence", 0.9}}),
  };
  std::vector<const EnsembleRun*> ptr;
  for (const EnsembleRun& r : runs) ptr.push_back(&r);
  const std::vector<std::string> zones = {"left", "wall"};
  const ProtectedStats g = protectedStatistics(zones, ptr);
  EXPECT_EQ(g.runs, 5);
  EXPECT_EQ(g.anyHits, 3);
  EXPECT_DOUBLE_EQ(g.pAny, 0.6);
  EXPECT_NEAR(g.meanMass, 3.5 / 5, 1e-15);
  EXPECT_DOUBLE_EQ(g.medianReach95, 0.5);  // left95 only: the right side receives
  EXPECT_DOUBLE_EQ(g.level, 0.05);
  EXPECT_DOUBLE_EQ(g.confidence, 0.9);
  ASSERT_EQ(g.zones.size(), 2u);
  const ZoneStats& wall = g.zones[1];
  EXPECT_EQ(wall.hits, 2);
  EXPECT_DOUBLE_EQ(wall.p, 0.4);
  // Wilson 2/5: (0.4 + 0.38416 -+ 1.96 sqrt(0.048 + 0.038416)) / 1.76832.
  EXPECT_NEAR(wall.lo, 0.117618, 1e-6);
  EXPECT_NEAR(wall.hi, 0.769280, 1e-6);
  EXPECT_DOUBLE_EQ(wall.massMedian, 0);
  EXPECT_DOUBLE_EQ(wall.massMax, 2);
  EXPECT_EQ(wall.flyrockRuns, 1);
  EXPECT_DOUBLE_EQ(wall.pFlyrock, 0.2);
  EXPECT_FALSE(wall.shown);
  const ZoneStats& left = g.zones[0];
  EXPECT_EQ(left.hits, 1);
  EXPECT_NEAR(left.lo, 0.036223, 1e-6);  // Wilson 1/5
  EXPECT_NEAR(left.hi, 0.624472, 1e-6);
  EXPECT_TRUE(hitsProtected(runs[1], zones));
  EXPECT_FALSE(hitsProtected(runs[2], zones));
  EXPECT_DOUBLE_EQ(protectedReach95(runs[1], zones), 3);
  EXPECT_DOUBLE_EQ(protectedReach95(runs[1], {"left", "right"}), 12);
}

// The ensemble picture: u beyond the footprint on both sides, the zones
// marked, the legend in a strip below the charts; one panel when the debris is
// contiguous in every run (the two curves agree), two when it is not.
TEST(SiteZones, EnsemblePictureMarksZonesAndKeepsItsLegendApart) {
  auto debrisRun = [](int plan, int sample, double left, double right,
                      std::vector<std::pair<double, double>> cover) {
    EnsembleRun r = run({{"footprint_xmin", 0}, {"footprint_xmax", 10}, {"left", left},
                         {"right", right}, {"site_xmin", -5}, {"site_xmax", 30},
                         {"mass_left", 0}, {"hit_left", 0}, {"mass_wall", 0}, {"hit_wall", 0},
                         {"x1_wall", -9}, {"x2_wall", -7}});
    r.plan = plan;
    r.sample = sample;
    r.cover = std::move(cover);
    return r;
  };
  EnsembleData data;
  data.zones = {"left", "wall"};
  data.runs = {debrisRun(1, 1, 0, 12, {{0, 22}}), debrisRun(1, 2, 1, 14, {{-1, 24}})};
  std::vector<PlanStats> plans = planStatistics(data);
  std::string svg = ensembleSvg(data, plans, "test");
  auto count = [](const std::string& s, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
    return n;
  };
  EXPECT_EQ(count(svg, "<svg x=\"0\""), 1u);  // contiguous: one panel
  EXPECT_NE(svg.find("beyond the footprint (m)"), std::string::npos);
  EXPECT_NE(svg.find("protected zones&apos; edges"), std::string::npos) << svg;
  EXPECT_NE(svg.find("site edges (protected: left)"), std::string::npos);
  EXPECT_EQ(count(svg, "class=\"legend\""), 1u);  // the strip only, no legend box in a chart
  // The strip starts below the chart (title 34 + 330).
  const std::size_t strip = svg.find("<g class=\"legend\"");
  const std::size_t line = svg.find("<line", strip);
  const std::size_t y1 = svg.find("y1=\"", line);
  EXPECT_GE(std::stod(svg.substr(y1 + 4)), 364.0);
  // A gap in the debris of one run: two panels.
  data.runs[1].cover = {{-1, 12}, {15, 24}};  // a gap beyond the footprint
  plans = planStatistics(data);
  svg = ensembleSvg(data, plans, "test");
  EXPECT_EQ(count(svg, "<svg x=\"0\""), 2u);
}

// decks/ensemble/protected_side.inp: both plans leave the site in every run;
// the felling toward the receiving side is best on the protected zones, though
// the drop on the neighbour's side reaches less.
TEST(SiteZones, ProtectedSideRanksTheFellingFirst) {
  namespace fs = std::filesystem;
  const fs::path out = fs::temp_directory_path() / "c2d_protected_side";
  fs::remove_all(out);
  DeckOptions o;
  o.outDir = out;
  o.quiet = true;
  const SolutionCommands commands;
  std::ostringstream console;
  const DeckOutcome r = runDeck(std::string(C2D_SOURCE_DIR) + "/decks/ensemble/protected_side.inp",
                                o, commands, console);
  ASSERT_EQ(r.exitCode, 0) << r.message;
  std::ifstream in(out / "protected_side_ensemble.csv");
  std::stringstream text;
  text << in.rdbuf();
  const EnsembleData data = readEnsembleTable(text.str(), 2);
  EXPECT_EQ(data.zones, (std::vector<std::string>{"left", "wall"}));
  const std::vector<PlanStats> plans = planStatistics(data);
  ASSERT_EQ(plans.size(), 2u);
  EXPECT_EQ(plans[0].pOutside, 1.0);
  EXPECT_EQ(plans[1].pOutside, 1.0);
  EXPECT_EQ(plans[0].protection.pAny, 0.0);
  EXPECT_EQ(plans[1].protection.pAny, 1.0);
  EXPECT_EQ(plans[0].pFelled, 1.0);
  EXPECT_EQ(plans[1].pFelled, 0.0);
  EXPECT_LT(plans[1].medianReach95, plans[0].medianReach95);  // the drop reaches less
  const std::string best = bestPlanText(data, plans);
  EXPECT_EQ(best.find("  best plan: 1 (L = 3, lean = 0.05)"), 0u) << best;
  fs::remove_all(out);
}

}  // namespace
}  // namespace c2d
