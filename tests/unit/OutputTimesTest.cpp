// Output never changes the computed motion (verification.md V15): the number
// and the times of a run's pictures, ParaView frames, TPLOt rows and printed
// tables leave its steps as they are, bit for bit, in every form of picture
// loop (macro/run/RunCursor.h); the outputs show the motion at the times asked
// for (solvers/DenseOutput.h); a loop that ends a phase ends on its tmax.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

using testing::DeckResult;
using testing::DeckTempDir;
using testing::expectRan;
using testing::readText;
using testing::runDeckText;

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// A bar dropped tilted onto a crushing ground with friction, under gravity
// tilted forward, with step cutting (the steps then land where they are told
// to), and dt = 3 ms, which the picture times 0.1, 0.35 do not divide.
const char* kBar = R"(FEAP * * bar dropped onto a crushing ground
  0 0 0 2 3 2

BLOCk
  CARTesian 4 0 1 1 1
  1 0 0.05
  2 2 0.35

MATErial,1
  FRAMe
    RESUltant STIFfness 1e7 1e7 1e5
    CROSs section 1 1e-3
    DENSity,,1
    FINIte

CONTact
  GROUnd,,0,1e4,1,0.5,0.3

GRAVity,,1,-9.81

END
BATCh
  DYNAmic,ENERgy,0.1,0.1
  AUTO,CUT,1e-6,1
  DT,,3e-3
  TPLOt
)";
const char* kData = "END\ndisp,3,2\ndisp,5,1\nener\n\nSTOP\n";

std::string timeLoop(const std::string& time) {
  return "  LOOP,,100000\n    " + time + "\n    LOOP,,20\n      TANG,,1\n    NEXT\n  NEXT\n";
}

// The history of a run of the bar with these commands, every step a row.
std::string barHistory(const DeckTempDir& dir, const std::string& name, const std::string& batch,
                       DeckResult* result = nullptr) {
  const DeckResult r = runDeckText(dir, name + ".inp", std::string(kBar) + batch + kData);
  EXPECT_EQ(r.outcome.exitCode, 0) << r.outcome.message << r.log;
  if (result) *result = r;
  return readText(r.out / (name + "_tplot.csv"));
}

TEST(OutputTimes, PictureLoopsLeaveTheStepsOfTheMotionUnchanged) {
  DeckTempDir dir;
  // One loop to t = 0.6 s, no picture.
  const std::string plain = barHistory(dir, "plain", timeLoop("TIME,,0.6"));
  ASSERT_GT(count(plain, "\n"), 150);
  // Six pictures, frames and tables at times set by a parameter.
  DeckResult six;
  const std::string pictures = barHistory(
      dir, "six",
      "  PARAmeter,tf,0\n  PVIEw\n  LOOP,,6\n    PARAmeter,tf,tf+0.1\n" + timeLoop("TIME,,tf") +
          "    PLOT,DEFOrmed\n    PVIEw\n    DISP,,3\n    STRE,,1\n  NEXT\n",
      &six);
  EXPECT_EQ(pictures, plain);
  // Loops written one after the other, with pictures and tables between them.
  EXPECT_EQ(barHistory(dir, "written",
                       timeLoop("TIME,,0.1") + "  PLOT,DEFOrmed\n" + timeLoop("TIME,,0.35") +
                           "  PLOT,DEFOrmed\n  DISP,,3\n  REAC,,1\n" + timeLoop("TIME,,0.6")),
            plain);
  // Loops that also stop at rest (a ratio the bar's kinetic energy stays
  // above up to 0.6 s: it sticks by 0.3 s and rings down on its friction).
  EXPECT_EQ(barHistory(dir, "rest",
                       "  PARAmeter,tf,0\n  LOOP,,12\n    PARAmeter,tf,tf+0.05\n" +
                           timeLoop("TIME,REST,tf,1e-30,0.1") + "    PLOT,DEFOrmed\n  NEXT\n"),
            plain);
  // A checkpoint between two loops changes nothing either.
  EXPECT_EQ(barHistory(dir, "saved", timeLoop("TIME,,0.1") + "  SAVE\n" + timeLoop("TIME,,0.6")),
            plain);

  // The pictures and frames show the motion at the times asked for: the
  // steps end at 0.102, 0.201, ..., the pictures say 0.1, 0.2, ...
  for (const char* t : {"0.1", "0.2", "0.4", "0.5"})
    EXPECT_NE(six.log.find(std::string("svg at t = ") + t + " (within step"), std::string::npos)
        << t << "\n"
        << six.log;
  const std::string pvd = readText(six.out / "six.pvd");
  for (const char* t : {"\"0\"", "\"0.1\"", "\"0.2\"", "\"0.3\"", "\"0.4\"", "\"0.5\"", "\"0.6\""})
    EXPECT_NE(pvd.find(std::string("timestep=") + t), std::string::npos) << t << "\n" << pvd;
  EXPECT_EQ(count(pvd, "<DataSet"), 7);
  EXPECT_EQ(count(six.log, "PLOT   deformed shape: six_deformed_"), 6);
}

TEST(OutputTimes, ALoopThatEndsAPhaseEndsOnItsTmax) {
  DeckTempDir dir;
  // Before a command that changes the analysis (DT here) the last step is
  // shortened to end on t = 0.1; so is the last one of the run, on 0.6.
  DeckResult phases;
  barHistory(dir, "phases",
             timeLoop("TIME,,0.1") + "  PLOT,DEFOrmed\n  DT,,3e-3\n" + timeLoop("TIME,,0.6"),
             &phases);
  EXPECT_NE(phases.log.find("  TIME   t = 1.000000e-01"), std::string::npos) << phases.log;
  EXPECT_NE(phases.log.find("  TIME   t = 6.000000e-01"), std::string::npos) << phases.log;
  EXPECT_NE(phases.log.find("PLOT   deformed shape: phases_deformed_0034.svg\n"),
            std::string::npos);
  // Before another time loop it is not: the step passes 0.1.
  DeckResult going;
  barHistory(dir, "going", timeLoop("TIME,,0.1") + timeLoop("TIME,,0.6"), &going);
  EXPECT_EQ(going.log.find("  TIME   t = 1.000000e-01"), std::string::npos) << going.log;
  EXPECT_NE(going.log.find("  TIME   t = 6.000000e-01"), std::string::npos) << going.log;
}

// The demolition fall of the paper's six-storey frame at the regression size
// (84 elements, ground contact only: about 0.5 s a run), with a picture loop
// driven by parameters and TIME,REST (decks/collapse/six_story_fall.inc).
std::string sixStoryFall(int frames, int tplotEvery, int viewEvery) {
  return "PARAmeter\n  nc = 2\n  nb = 4\n  P = 100\n  ksb = -393\n  ksc = -723\n  push = 3.0\n"
         "  tend = 12\n  kmem = 0\n  zeta = 0.03\n  fd = 40\n  tpinc = " +
         std::to_string(tplotEvery) + "\n  pvinc = " + std::to_string(viewEvery) +
         "\n  frames = " + std::to_string(frames) + "\n\nINCLude," + C2D_SOURCE_DIR +
         "/decks/collapse/six_story_fall.inc\n\nSTOP\n";
}

// The last ParaView file of a run (its final state).
std::string lastView(const std::filesystem::path& dir, const std::string& stem) {
  const std::string pvd = readText(dir / (stem + ".pvd"));
  const std::size_t at = pvd.rfind("file=\"");
  if (at == std::string::npos) return {};
  const std::size_t end = pvd.find('"', at + 6);
  return readText(dir / pvd.substr(at + 6, end - at - 6));
}

TEST(OutputTimes, TheDemolitionFallWritesTheSameDebrisWithFourOrTwelvePictures) {
  DeckTempDir dir;
  const DeckResult four = runDeckText(dir, "four.inp", sixStoryFall(4, 20, 20));
  expectRan(four);
  const DeckResult twelve = runDeckText(dir, "twelve.inp", sixStoryFall(12, 7, 13));
  expectRan(twelve);
  const std::string debris = readText(four.out / "four_debris.csv");
  ASSERT_NE(debris.find("left,right"), std::string::npos);
  EXPECT_EQ(debris, readText(twelve.out / "twelve_debris.csv"));
  // The final state as ParaView gets it, and the last row of the history.
  const std::string view = lastView(four.out, "four");
  ASSERT_FALSE(view.empty());
  EXPECT_EQ(view, lastView(twelve.out, "twelve"));
  const auto lastRow = [](const std::string& csv) {
    return csv.substr(csv.rfind('\n', csv.size() - 2) + 1);
  };
  EXPECT_EQ(lastRow(readText(four.out / "four_tplot.csv")),
            lastRow(readText(twelve.out / "twelve_tplot.csv")));
  // Pictures at the end of the push and every tend/frames of the fall until
  // it is at rest: once at rest the later pictures would repeat the last one,
  // and the log says so once.
  EXPECT_EQ(count(twelve.log, "no step since"), 1) << twelve.log;
  EXPECT_EQ(count(twelve.log, "(the motion is at rest): it is not drawn again"), 1);
  const std::regex at("svg at t = ([0-9.]+) \\(within step");
  std::vector<std::string> times;
  for (std::sregex_iterator i(twelve.log.begin(), twelve.log.end(), at), e; i != e; ++i)
    times.push_back((*i)[1]);
  // Every picture within a step is at a scheduled time (t = 3, 4, ... s;
  // a step that ends on one draws it without sampling).
  ASSERT_GE(times.size(), 2u) << twelve.log;
  for (const std::string& t : times)
    EXPECT_TRUE(std::regex_match(t, std::regex("[0-9]+"))) << t << "\n" << twelve.log;
}

}  // namespace
}  // namespace c2d
