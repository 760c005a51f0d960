// The floor loads of the six-story decks (decks/paper/six_story_loads.inc,
// six_story_joints.inc) against the frame's geometry: every beam-column joint
// of levels 1 to 6 of the three columns carries P (and, for the demolition
// fall, the mass P/g), no other node does, for the three meshes of the paper.
// The nodes are identified by their coordinates in the log's echo, not by
// their numbers, so a record that generates into the wrong column fails here.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>
#include <string>

#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

using NodeTable = std::map<int, std::vector<double>>;

// The rows "node v1 v2 ..." of the last table titled `title` in the log.
NodeTable lastTable(const std::string& log, const std::string& title) {
  NodeTable rows;
  const auto at = log.rfind(title);
  if (at == std::string::npos) return rows;
  std::istringstream in(log.substr(at));
  std::string line;
  std::getline(in, line);  // the title
  std::getline(in, line);  // blank
  std::getline(in, line);  // column names
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    int node = 0;
    if (!(ls >> node)) break;
    std::vector<double> v;
    for (double x; ls >> x;) v.push_back(x);
    rows[node] = v;
  }
  return rows;
}

bool isFloorJoint(const std::vector<double>& xy) {
  const double x = xy.at(0), y = xy.at(1);
  const bool onColumn = std::abs(x) < 1e-9 || std::abs(x - 4) < 1e-9 || std::abs(x - 8) < 1e-9;
  const double level = y / 3;
  return onColumn && std::abs(level - std::round(level)) < 1e-9 && level > 0.5;
}

class SixStoryLoads : public ::testing::TestWithParam<std::pair<int, int>> {};

TEST_P(SixStoryLoads, EveryFloorJointAndNothingElse) {
  const auto [nc, nb] = GetParam();
  const std::string paper = std::string(C2D_SOURCE_DIR) + "/decks/paper/";
  const double P = 100, g = 9.81;
  // The loads as the failure phase reads them, then the fall's: forces off,
  // masses P/g at the same joints (decks/collapse/six_story_fall.inc).
  const std::string deck = "PARAmeter\n  nc = " + std::to_string(nc) +
                           "\n  nb = " + std::to_string(nb) +
                           "\n  P = 100\n\n"
                           "FEAP * * six-story loads\n  0 0 0 2 3 2\n\n"
                           "INCLude," +
                           paper +
                           "six_story_frame.inc\n\n"
                           "MATErial,1\n  FRAMe\n    RESUltant STIFfness 3.6e6 1.2e6 48000\n\n"
                           "MATErial,2\n  FRAMe\n    RESUltant STIFfness 3.6e6 1.2e6 48000\n\n"
                           "END\nBATCh\n  MESH," +
                           paper + "six_story_loads.inc\n" +
                           "  MESH\nEND\n"
                           "PARAmeter\n  jfy = 0\n  jm = P/9.81\n\n"
                           "INCLude," +
                           paper + "six_story_joints.inc\n\nEND\nSTOP\n";
  const testing::DeckTempDir dir;
  const auto first = testing::runDeckText(dir, "loads.inp", deck);
  ASSERT_EQ(first.outcome.exitCode, 0) << first.outcome.message << first.console;
  const std::string& log = first.log;
  const NodeTable coords = lastTable(log, "N o d a l   C o o r d i n a t e s");
  ASSERT_EQ(coords.size(), static_cast<std::size_t>(3 * (6 * nc + 1) + 12 * (nb - 1)));

  // The failure phase: the forces of the first MESH (the echo before the second one).
  const std::string failure = log.substr(0, log.rfind("N o d a l   F o r c e s"));
  const NodeTable forces = lastTable(failure, "N o d a l   F o r c e s");
  const NodeTable masses = lastTable(log, "N o d a l   M a s s e s");
  const NodeTable forcesAfter = lastTable(log, "N o d a l   F o r c e s");
  std::map<int, double> perLevel, massPerLevel;
  int joints = 0;
  for (const auto& [node, xy] : coords) {
    const bool joint = isFloorJoint(xy);
    joints += joint;
    const int level = static_cast<int>(std::round(xy[1] / 3));
    const auto f = forces.find(node);
    const double fy = f == forces.end() ? 0.0 : f->second.at(1);
    const double fx = f == forces.end() ? 0.0 : f->second.at(0);
    EXPECT_EQ(fx, 0.0) << "node " << node;
    EXPECT_EQ(fy, joint ? -P : 0.0) << "node " << node << " at (" << xy[0] << ", " << xy[1] << ")";
    if (joint) perLevel[level] += fy;
    const auto m = masses.find(node);
    const double mx = m == masses.end() ? 0.0 : m->second.at(0);
    const double my = m == masses.end() ? 0.0 : m->second.at(1);
    EXPECT_NEAR(mx, joint ? P / g : 0.0, 1e-3) << "node " << node;
    EXPECT_NEAR(my, joint ? P / g : 0.0, 1e-3) << "node " << node;
    if (joint) massPerLevel[level] += my;
    const auto fa = forcesAfter.find(node);
    if (fa != forcesAfter.end()) {
      EXPECT_EQ(fa->second.at(1), 0.0) << "node " << node;
    }
  }
  EXPECT_EQ(joints, 18);
  ASSERT_EQ(perLevel.size(), 6u);
  for (const auto& [level, sum] : perLevel) {
    EXPECT_EQ(sum, -3 * P) << "level " << level;
    EXPECT_NEAR(massPerLevel[level], 3 * P / g, 2e-3) << "level " << level;
  }
}

INSTANTIATE_TEST_SUITE_P(PaperMeshes, SixStoryLoads,
                         ::testing::Values(std::pair{2, 4}, std::pair{4, 6}, std::pair{8, 12}));

}  // namespace
}  // namespace c2d
