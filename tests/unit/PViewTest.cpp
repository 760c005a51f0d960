// PVIEw (ParaView collection): PVIEw,,inc writes the current state and then
// every inc committed steps, the .pvd lists every .vtu with its time, each .vtu
// is well-formed with one point per node and one cell per element and holds the
// closed-form displacements; PVIEw,OFF stops the automatic output; the slave
// node of a condensed joint shows its own state (master translations, its
// member's rotation), not zeros.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/unit/OutputTestSupport.h"
#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

using testing::DeckTempDir;
using testing::numbers;
using testing::readText;
using testing::XmlNode;
using testing::XmlReader;

const std::string kParams = "PARAmeter\n  L = 3\n  n = 2\n  P = 10\n\n";

const XmlNode* dataArray(const XmlNode& vtu, const std::string& name) {
  for (const XmlNode* d : vtu.all("DataArray"))
    if (d->attr("Name") == name) return d;
  return nullptr;
}

TEST(PView, CollectionEveryIncSteps) {
  DeckTempDir dir;
  const auto r =
      testing::runDeckText(dir, "pv.inp", kParams + testing::rampProblem(4, "  PVIEw,,2\n", ""));
  ASSERT_EQ(r.outcome.exitCode, 0) << r.outcome.message;
  const XmlNode pvd = XmlReader::parse(readText(r.out / "pv.pvd"));
  const auto sets = pvd.all("DataSet");
  ASSERT_EQ(sets.size(), 3u);  // the initial state, steps 2 and 4
  const double times[] = {0, 0.5, 1};
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_DOUBLE_EQ(std::stod(sets[i]->attr("timestep")), times[i]);
    const std::string file = "pv_000" + std::to_string(i) + ".vtu";
    EXPECT_EQ(sets[i]->attr("file"), file);
    const XmlNode vtu = XmlReader::parse(readText(r.out / file));
    const auto piece = vtu.all("Piece");
    ASSERT_EQ(piece.size(), 1u);
    EXPECT_EQ(piece[0]->attr("NumberOfPoints"), "3");
    EXPECT_EQ(piece[0]->attr("NumberOfCells"), "2");
    const XmlNode* u = dataArray(vtu, "displacement");
    ASSERT_NE(u, nullptr);
    const auto v = numbers(u->text);
    ASSERT_EQ(v.size(), 9u);
    EXPECT_NEAR(v[7], times[i] * testing::cantileverTip(10, 3, 2), 1e-15);  // node 3, y
  }
  EXPECT_FALSE(std::filesystem::exists(r.out / "pv_0003.vtu"));
}

TEST(PView, FinalStateEndsTheCollection) {
  // Five steps, output every second: the initial state, steps 2 and 4, and the
  // final step 5 although 5 is not a multiple of 2. Times as the deck gives them.
  DeckTempDir dir;
  const auto r =
      testing::runDeckText(dir, "fin.inp", kParams + testing::rampProblem(5, "  PVIEw,,2\n", ""));
  ASSERT_EQ(r.outcome.exitCode, 0) << r.outcome.message;
  const XmlNode pvd = XmlReader::parse(readText(r.out / "fin.pvd"));
  const auto sets = pvd.all("DataSet");
  ASSERT_EQ(sets.size(), 4u);
  const char* times[] = {"0", "0.4", "0.8", "1"};
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(sets[i]->attr("timestep"), times[i]);
  const XmlNode last = XmlReader::parse(readText(r.out / "fin_0003.vtu"));
  const auto u = numbers(dataArray(last, "displacement")->text);
  ASSERT_EQ(u.size(), 9u);
  EXPECT_NEAR(u[7], testing::cantileverTip(10, 3, 2), 1e-15);
}

TEST(PView, OffStopsTheAutomaticOutput) {
  DeckTempDir dir;
  // Every step from the start; off after two loaded steps. TIME commits the
  // previous step, so step 1 is written, step 2 (committed by the next TIME,
  // after PVIEw,OFF) is not; the last PVIEw writes the final state.
  const std::string batch =
      "  PROP,,1\n  DT,,0.25\n  TPLOt\n  PVIEw,,1\n"
      "  LOOP,,2\n    TIME\n    LOOP,,5\n      TANG,,1\n    NEXT\n  NEXT\n"
      "  PVIEw,OFF\n"
      "  LOOP,,2\n    TIME\n    LOOP,,5\n      TANG,,1\n    NEXT\n  NEXT\n"
      "  PVIEw\n";
  const auto r = testing::runDeckText(dir, "off.inp", kParams + testing::cantileverProblem(batch, testing::rampData()));
  ASSERT_EQ(r.outcome.exitCode, 0) << r.outcome.message;
  const XmlNode pvd = XmlReader::parse(readText(r.out / "off.pvd"));
  const auto sets = pvd.all("DataSet");
  ASSERT_EQ(sets.size(), 3u);
  EXPECT_DOUBLE_EQ(std::stod(sets[0]->attr("timestep")), 0);
  EXPECT_DOUBLE_EQ(std::stod(sets[1]->attr("timestep")), 0.25);
  EXPECT_DOUBLE_EQ(std::stod(sets[2]->attr("timestep")), 1);
}

TEST(PView, SlaveNodeOfACondensedJointShowsItsState) {
  // Clamped member 1-2 (length a) and member 3-4 (length a) joined at 2 = 3 by a
  // revolute joint, node 4 on a vertical roller, load P down at the joint. The
  // pinned-pinned member 3-4 carries no shear, so the joint deflects like a
  // cantilever tip, v = -P (a^3/(3 EI) (1 - 1/4) + a/GA), and member 3-4 turns
  // rigidly: the slave's rotation is -v/a (counterclockwise +), the master's the
  // cantilever's.
  DeckTempDir dir;
  const std::string deck =
      "PARAmeter\n  a = 2\n  P = 10\n\n"
      "FEAP * * jointed beam\n  0 0 0 2 3 2\n\n"
      "COORdinates\n  1 0 0 0\n  2 0 a 0\n  3 0 a 0\n  4 0 2*a 0\n\n"
      "ELEMents\n  1 0 1 1 2\n  2 0 1 3 4\n\n"
      "MATErial,1\n  FRAMe\n    RESUltant STIFfness 3.6e6 500000 48000\n\n"
      "BOUNdary\n  1 0 1 1 1\n  4 0 0 1 0\n\n"
      "JOINt\n  2 3\n\n"
      "FORCe\n  2 0 0 -P 0\n\n"
      "END\nBATCh\n  LOOP,,5\n    TANG,,1\n  NEXT\n  PVIEw\n  PLOT,DEFO\nEND\nSTOP\n";
  const auto r = testing::runDeckText(dir, "joint.inp", deck);
  ASSERT_EQ(r.outcome.exitCode, 0) << r.outcome.message;
  const XmlNode vtu = XmlReader::parse(readText(r.out / "joint_0000.vtu"));
  const auto u = numbers(dataArray(vtu, "displacement")->text);
  const auto rot = numbers(dataArray(vtu, "rotation")->text);
  const auto joint = numbers(dataArray(vtu, "joint")->text);
  ASSERT_EQ(u.size(), 12u);
  ASSERT_EQ(rot.size(), 4u);
  const double v = -10 * (8 / (3 * 48000.0) * 0.75 + 2 / 500000.0);
  EXPECT_NEAR(u[4], v, 1e-12);          // master y
  EXPECT_NEAR(u[7], v, 1e-12);          // slave y: the master's
  EXPECT_NEAR(u[6], u[3], 1e-15);       // slave x: the master's
  EXPECT_NEAR(rot[2], -v / 2, 1e-10);   // slave: member 3-4 turning rigidly
  EXPECT_LT(rot[1], 0);                 // master: the cantilever's clockwise tip rotation
  EXPECT_GT(std::abs(rot[2] - rot[1]), 1e-5);
  EXPECT_EQ(joint, (std::vector<double>{0, 1, 1, 0}));
  // The picture marks the joint once and draws both members.
  const XmlNode svg = XmlReader::parse(readText(r.out / "joint_deformed_0000.svg"));
  EXPECT_EQ(svg.all("path", "member").size(), 2u);
  EXPECT_EQ(svg.all("circle", "joint").size(), 2u);  // on the frame and in the key
}

}  // namespace
}  // namespace c2d
