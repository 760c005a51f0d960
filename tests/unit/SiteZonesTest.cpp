// The site's protected zones and flying fragments: a fragment apart from the
// bed and the zones' figures of a run (core/Debris, core/DebrisZones), and
// decks/ensemble/protected_side.inp's plans ranked by their protected zones.
// The zones' statistics, the sample-size rule's bound and the ensemble
// picture: ZoneStatisticsTest, BinomialBoundTest, EnsemblePictureTest.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "elements/ElementFactory.h"
#include "macro/DeckRunner.h"
#include "macro/output/Debris.h"
#include "macro/output/DebrisZones.h"
#include "macro/studies/BinomialBound.h"
#include "macro/studies/EnsemblePicture.h"
#include "macro/studies/PlanStatistics.h"
#include "macro/studies/Statistics.h"
#include "macro/studies/ZoneStatistics.h"
#include "tests/unit/DeckTestSupport.h"
#include "tests/unit/ElementTestSupport.h"
#include "tests/unit/RunDeckSupport.h"

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

// decks/ensemble/protected_side.inp: both plans leave the site in every run;
// the felling toward the receiving side is best on the protected zones, though
// the drop on the neighbour's side reaches less.
TEST(SiteZones, ProtectedSideRanksTheFellingFirst) {
  namespace fs = std::filesystem;
  const testing::DeckTempDir scratch;
  const testing::DeckResult ran = testing::runSourceDeck(scratch, "ensemble/protected_side.inp");
  const fs::path& out = ran.out;
  const DeckOutcome& r = ran.outcome;
  ASSERT_EQ(r.exitCode, 0) << r.message;
  const EnsembleData data =
      readEnsembleTable(testing::readText(out / "protected_side_ensemble.csv"), 2);
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
}

}  // namespace
}  // namespace c2d
