// AUTO,CUT through impacts: a step that ImpactSteps proposed shorter than the
// deck's DT and that did not converge is taken again shorter. Before, the cut
// halved DT only, and a proposal not longer than the halved DT took the step
// again as it was, through the same iterates (the main example with member
// contact repeated 174 of its 1200 cut steps so, up to 30 iterations each).
#include <gtest/gtest.h>

#include <cstdlib>
#include <sstream>
#include <string>

#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

// A bar dropped from 1 m, slightly tilted, onto a crushing ground with
// friction, three Newton iterations a step: steps through its impacts fail and
// are cut (one of them, before, with the proposal not longer than half DT).
const char* kDrop =
    "FEAP * * bar dropped on a crushing ground, three iterations a step\n"
    "  0 0 0 2 3 2\n\n"
    "BLOCk\n  CARTesian 2 0 1 1 1\n  1 0 1\n  2 2 1.05\n\n"
    "MATErial,1\n  FRAMe\n    RESUltant STIFfness 1e7 1e7 1e5\n"
    "    CROSs section 1 1e-3\n    DENSity,,1\n    FINIte\n\n"
    "CONTact\n  GROUnd,,0,1e5,1,0.5,0.3\n\n"
    "GRAVity,,0,-9.81\n\n"
    "END\nBATCh\n  DYNAmic,ENERgy,0.1,0.1\n  AUTO,CUT,1e-7\n  DT,,0.01\n"
    "  LOOP,,300\n    TIME\n    LOOP,,3\n      TANG,,1\n    NEXT\n  NEXT\nEND\nSTOP\n";

TEST(StepCutting, ACutStepThroughAnImpactIsTakenAgainShorter) {
  const testing::DeckTempDir dir;
  const auto r = testing::runDeckText(dir, "drop.inp", kDrop);
  ASSERT_EQ(r.outcome.exitCode, 0) << r.console;
  ASSERT_NE(r.log.find("needs a shorter step through its impact"), std::string::npos);
  // The time each failed attempt reached ("*** Newton iteration ... (t = ...")
  // against the time of the attempt after its cut (its first iteration's line).
  std::istringstream in(r.log);
  std::string line;
  double failed = -1;
  int cuts = 0, repeated = 0;
  while (std::getline(in, line)) {
    if (line.rfind("  *** Newton iteration", 0) == 0) {
      const auto at = line.find("(t = ");
      ASSERT_NE(at, std::string::npos) << line;
      failed = std::strtod(line.c_str() + at + 5, nullptr);
    } else if (line.rfind("  TANG   step", 0) == 0 && failed >= 0) {
      const auto at = line.find("t = ");
      ASSERT_NE(at, std::string::npos) << line;
      const double t = std::strtod(line.c_str() + at + 4, nullptr);
      ++cuts;
      if (std::abs(t - failed) < 1e-7) ++repeated;
      failed = -1;
    }
  }
  EXPECT_GT(cuts, 3);
  EXPECT_EQ(repeated, 0) << "of " << cuts << " cut steps";
}

}  // namespace
}  // namespace c2d
