// QLOAd, MASS and SITE (macro/mesh/LoadCommands): what they put in the model, and
// their deck errors at file:line:col.
#include <gtest/gtest.h>

#include <climits>
#include <sstream>

#include "elements/ModelCheckpoint.h"
#include "solvers/ModelFingerprint.h"
#include "tests/unit/MeshBuildSupport.h"

namespace c2d {
namespace {

using testing::buildMesh;
using testing::expectMeshError;
using testing::kBeamMesh;

TEST(LoadCommands, QloadMassAndSiteEnterTheModel) {
  std::ostringstream echo;
  const Model m = buildMesh(kBeamMesh +
                                "GRAV,,0,-10\n"
                                "QLOAd\n 1 3 2 0 -5\n 2 0 0 1 -20 mass\n\n"
                                "MASS\n 1 2 2 2 0.1\n 3 0 4 4 0\n\n"
                                "SITE,,-2,8\n",
                            &echo);
  ASSERT_EQ(m.elementLoads().size(), 3u);
  EXPECT_EQ(m.elementLoads()[0].element, 0);
  EXPECT_EQ(m.elementLoads()[1].element, 2);  // 1..3 step 2
  EXPECT_EQ(m.elementLoads()[1].q.y(), -5);
  EXPECT_FALSE(m.elementLoads()[1].asMass);
  EXPECT_EQ(m.elementLoads()[2].element, 1);  // n2 = 0: n1 only
  EXPECT_TRUE(m.elementLoads()[2].asMass);
  EXPECT_EQ(m.elementLoads()[2].q.x(), 1);
  // MASS generation 1 -> 3 with increment 2 interpolates nothing between (no node 2 step);
  // node 2 keeps zero, 1 and 3 get their values.
  EXPECT_EQ(m.nodalMass(0)[0], 2);
  EXPECT_EQ(m.nodalMass(0)[2], 0.1);
  EXPECT_EQ(m.nodalMass(2)[1], 4);
  ASSERT_TRUE(m.site().has_value());
  EXPECT_EQ(m.site()->xmin, -2);
  EXPECT_EQ(m.site()->xmax, 8);
  EXPECT_NE(echo.str().find("N o d a l   M a s s e s"), std::string::npos);
  EXPECT_NE(echo.str().find("S i t e"), std::string::npos);

  const Model g = buildMesh(kBeamMesh + "MASS\n 1 1 1 1 0\n 4 0 4 4 0\n\n");
  for (int n = 0; n < 4; ++n) EXPECT_DOUBLE_EQ(g.nodalMass(n)[1], n + 1.0);  // linear generation
}

// An increment near 2^31 ends the range (it overflowed the loop counter and
// crashed): QLOAd loads element 1 only, MASS generates nothing between its records.
TEST(LoadCommands, IncrementsNearIntMaxEndTheRange) {
  const std::string big = std::to_string(INT_MAX);
  const Model m = buildMesh(kBeamMesh + "QLOAd\n 1 3 " + big + " 0 -5\n\n" + "MASS\n 1 " + big +
                            " 1 1 0\n 4 0 2 2 0\n\n");
  ASSERT_EQ(m.elementLoads().size(), 1u);
  EXPECT_EQ(m.elementLoads()[0].element, 0);
  EXPECT_EQ(m.nodalMass(0)[0], 1);
  EXPECT_EQ(m.nodalMass(1)[0], 0);
  EXPECT_EQ(m.nodalMass(2)[0], 0);
  EXPECT_EQ(m.nodalMass(3)[0], 2);
  const Model down = buildMesh(kBeamMesh + "MASS\n 4 -" + big + " 1 1 0\n 1 0 2 2 0\n\n");
  EXPECT_EQ(down.nodalMass(3)[0], 1);
  EXPECT_EQ(down.nodalMass(2)[0], 0);
  EXPECT_EQ(down.nodalMass(0)[0], 2);
}

// A restart file keeps the floor loads, the nodal masses and the site.
TEST(LoadCommands, RestartKeepsThem) {
  const Model m = buildMesh(
      kBeamMesh + "GRAV,,0,-10\nQLOAd\n 2 0 0 0.5 -5 MASS\n\nMASS\n 4 0 1 2 3\n\nSITE,,-1,4\n");
  std::stringstream bytes(std::ios::in | std::ios::out | std::ios::binary);
  writeModel(bytes, m);
  const Model r = readModel(bytes, 0);
  ASSERT_EQ(r.elementLoads().size(), 1u);
  EXPECT_EQ(r.elementLoads()[0].element, 1);
  EXPECT_EQ(r.elementLoads()[0].q, Vec2(0.5, -5));
  EXPECT_TRUE(r.elementLoads()[0].asMass);
  EXPECT_EQ(r.nodalMass(3)[2], 3);
  ASSERT_TRUE(r.site().has_value());
  EXPECT_EQ(r.site()->xmax, 4);
}

// REST refuses a restart file of a deck whose floor loads, masses or site
// differ (the restored model would bring the saved ones back silently).
TEST(LoadCommands, TheRestartFingerprintSeesThem) {
  const std::string grav = "GRAV,,0,-10\n";
  const auto print = [&](const std::string& mesh) {
    return ModelFingerprint::of(buildMesh(kBeamMesh + grav + mesh));
  };
  const ModelFingerprint base = print("QLOAd\n 1 0 0 0 -5\n\nSITE,,-1,4\n");
  EXPECT_EQ(base.differences(print("QLOAd\n 1 0 0 0 -5\n\nSITE,,-1,4\n")), "");
  EXPECT_EQ(base.differences(print("QLOAd\n 1 0 0 0 -10\n\nSITE,,-1,4\n")),
            "loads (forces, prescribed values, load tables, floor loads, gravity, contact)");
  EXPECT_EQ(base.differences(print("QLOAd\n 1 0 0 0 -5 MASS\n\nSITE,,-1,4\n")),
            "masses (MASS, floor loads carried as mass)");
  EXPECT_EQ(base.differences(print("QLOAd\n 1 0 0 0 -5\n\nMASS\n 2 0 1 1 0\n\nSITE,,-1,4\n")),
            "masses (MASS, floor loads carried as mass)");
  EXPECT_EQ(base.differences(print("QLOAd\n 1 0 0 0 -5\n\nSITE,,-1,5\n")), "site (SITE)");
}

TEST(LoadCommands, Errors) {
  expectMeshError(kBeamMesh + "QLOAd\n 1 3 1 0 -5 WEIGHT\n\n", 16, 13, "unknown option 'WEIGHT'");
  expectMeshError(kBeamMesh + "QLOAd\n 2 5 1 0 -5\n\n", 16, 4, "QLOAd: element 4 is not defined");
  expectMeshError(kBeamMesh + "QLOAd\n 3 1 1 0 -5\n\n", 16, 4,
                  "the last element 1 comes before the first");
  expectMeshError(kBeamMesh + "QLOAd\n 1 3 1 0 -5 MASS\n\n", 16, 13,
                  "QLOAd with MASS needs GRAVity");
  expectMeshError(kBeamMesh + "MASS\n 2 0 1 -1 0\n\n", 16, 8, "a mass must not be negative");
  expectMeshError(kBeamMesh + "SITE,,5,1\n", 15, 9, "xmax must be greater than xmin");
  expectMeshError(kBeamMesh + "SITE,,5\n", 15, 8, "SITE needs xmin and xmax");
  expectMeshError(kBeamMesh + "SITE,1,5\n", 15, 6, "SITE takes no option word");
  expectMeshError(kBeamMesh + "SITE,X,1,5\n", 15, 6, "SITE takes no option word");
  // A second site or ground in one mesh input would silently replace the first.
  expectMeshError(kBeamMesh + "SITE,,-1,4\nSITE,,0,5\n", 16, 1,
                  "a second SITE (the first is on line 15)");
  expectMeshError(kBeamMesh + "CONTact\n GROUnd,,0,1e5\n\nCONTact\n GROUnd,,-1,1e5\n\n", 19, 2,
                  "a second GROUnd record (the first is on line 16)");
}

// SITE's direction and optional block: zones, FLYRock, RISK; without records
// (the command record alone, followed at once by a command) as decks wrote it.
TEST(LoadCommands, SiteZonesAndDirection) {
  const Model m = buildMesh(kBeamMesh +
                            "SITE,,-2,8,RIGHt\n"
                            " wall -6 -4 3 0.5\n"
                            " road,10,14\n"
                            " FLYRock,,0.2\n"
                            " RISK,,0.05,0.9\n"
                            "\n"
                            "GRAV,,0,-10\n");
  ASSERT_TRUE(m.site().has_value());
  const Site& s = *m.site();
  EXPECT_EQ(s.dir, FallDirection::Right);
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_EQ(s.objects[0].name, "wall");
  EXPECT_EQ(s.objects[0].x1, -6);
  EXPECT_EQ(s.objects[0].x2, -4);
  EXPECT_EQ(s.objects[0].height, 3);
  EXPECT_EQ(s.objects[0].mass, 0.5);
  EXPECT_EQ(s.objects[1].name, "road");
  EXPECT_EQ(s.objects[1].height, 0);
  EXPECT_EQ(s.objects[1].mass, 0);
  EXPECT_EQ(s.flyrockMass, 0.2);
  EXPECT_EQ(s.riskLevel, 0.05);
  EXPECT_EQ(s.riskConfidence, 0.9);
  EXPECT_EQ(m.gravity().y(), -10);
  // The right side receives the debris: the zones are left, wall, road.
  const auto zones = protectedZones(s);
  ASSERT_EQ(zones.size(), 3u);
  EXPECT_EQ(zones[0].name, "left");
  EXPECT_EQ(zones[0].x2, -2);
  EXPECT_EQ(zones[1].name, "wall");

  // No records: the next command follows at once (or after a blank record).
  for (const char* tail :
       {"SITE,,-2,8,down\nGRAV,,0,-10\n", "SITE,,-2,8,LEFT\n\nGRAV,,0,-10\n", "SITE,,-2,8\n"}) {
    const Model n = buildMesh(kBeamMesh + tail);
    ASSERT_TRUE(n.site().has_value()) << tail;
    EXPECT_TRUE(n.site()->objects.empty()) << tail;
    EXPECT_EQ(n.site()->flyrockMass, -1) << tail;
  }
  EXPECT_EQ(buildMesh(kBeamMesh + "SITE,,-2,8,down\nGRAV,,0,-10\n").site()->dir,
            FallDirection::Down);
  EXPECT_EQ(protectedZones(*buildMesh(kBeamMesh + "SITE,,-2,8,LEFT\n").site()).front().name,
            "right");

  // The restart file and the fingerprint keep them.
  std::stringstream bytes(std::ios::in | std::ios::out | std::ios::binary);
  writeModel(bytes, m);
  const Model r = readModel(bytes, 0);
  ASSERT_TRUE(r.site().has_value());
  EXPECT_EQ(r.site()->dir, FallDirection::Right);
  ASSERT_EQ(r.site()->objects.size(), 2u);
  EXPECT_EQ(r.site()->objects[0].name, "wall");
  EXPECT_EQ(r.site()->objects[0].mass, 0.5);
  EXPECT_EQ(r.site()->flyrockMass, 0.2);
  EXPECT_EQ(r.site()->riskConfidence, 0.9);
  EXPECT_EQ(ModelFingerprint::of(r).site, ModelFingerprint::of(m).site);
  EXPECT_NE(
      ModelFingerprint::of(buildMesh(kBeamMesh + "SITE,,-2,8,RIGHt\n wall -6 -4 3 0.4\n\n")).site,
      ModelFingerprint::of(buildMesh(kBeamMesh + "SITE,,-2,8,RIGHt\n wall -6 -4 3 0.5\n\n")).site);
}

TEST(LoadCommands, SiteBlockErrors) {
  expectMeshError(kBeamMesh + "SITE,,-2,8,UP\n", 15, 12, "unknown direction 'UP'");
  expectMeshError(kBeamMesh + "SITE,,-2,8\n left -6 -4\n\n", 16, 2, "'left' is the name of a side");
  expectMeshError(kBeamMesh + "SITE,,-2,8\n w-1 -6 -4\n\n", 16, 2, "'w-1' is not a zone name");
  expectMeshError(kBeamMesh + "SITE,,-2,8\n wall -4 -6\n\n", 16, 10, "x2 must be greater than x1");
  expectMeshError(kBeamMesh + "SITE,,-2,8\n wall -6\n\n", 16, 9, "the zone needs x1 and x2");
  expectMeshError(kBeamMesh + "SITE,,-2,8\n wall -6 -4 -1\n\n", 16, 13,
                  "the height must not be negative");
  expectMeshError(kBeamMesh + "SITE,,-2,8\n wall -6 -4 0 -1\n\n", 16, 15,
                  "the mass must not be negative");
  expectMeshError(kBeamMesh + "SITE,,-2,8\n wall -6 -4\n Wall 1 2\n\n", 17, 2,
                  "a second zone named 'Wall'");
  expectMeshError(kBeamMesh + "SITE,,-2,8\n FLYRock,,-1\n\n", 16, 11,
                  "the flyrock mass must not be negative");
  expectMeshError(kBeamMesh + "SITE,,-2,8\n RISK,,1.5\n\n", 16, 8, "the risk p must lie in (0, 1)");
  expectMeshError(kBeamMesh + "SITE,,-2,8\n RISK,,0.01,95\n\n", 16, 13,
                  "the confidence must lie in (0, 1)");
  expectMeshError(kBeamMesh + "SITE,,-2,8\n wall -6 -4\nGRAV,,0,-10\n", 17, 1,
                  "the data set of 'SITE' (line 15) is not ended by a blank record");
}

}  // namespace
}  // namespace c2d
