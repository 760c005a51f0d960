// A deck's summary is its runs' summaries added (RunSummary::operator+=):
// counts summed, the worst figures kept, the flags or-ed; the summary's words
// for the energy error and its warnings (runSummaryText, runWarnings).
#include <gtest/gtest.h>

#include "macro/run/RunSummary.h"
#include "tests/unit/DeckTestSupport.h"

namespace c2d {
namespace {

using testing::contains;

RunSummary first() {
  RunSummary s;
  s.steps = 10, s.iterations = 31, s.factorizations = 29, s.cuts = 1, s.hinges = 2;
  s.energyError = 3e-9, s.energyGained = 2e-5, s.gainStep = 7, s.gainTime = 0.35;
  s.seconds = 1.5, s.maxMomentRatio = 0.98;
  s.jointsFormed = 1, s.fractures = 1, s.removed = 2, s.crossings = 1;
  s.memberContact = true, s.debrisRuns = 1, s.outsideRuns = 1, s.kineticRatio = 2e-3;
  s.unintendedRuns = 1, s.verdict = "backwards";
  return s;
}

RunSummary second() {
  RunSummary s;
  s.steps = 5, s.iterations = 12, s.factorizations = 12, s.cuts = 3, s.hinges = 4;
  s.energyError = 1e-10, s.energyGained = 4e-5, s.gainStep = 3, s.gainTime = 0.15;
  s.seconds = 0.25, s.dynamic = true, s.maxMomentRatio = 1.01;
  s.jointsRuptured = 2, s.shears = 1, s.folded = 2, s.sunk = 1, s.blastsNotMade = 1;
  s.debrisRuns = 1, s.movingRuns = 1, s.kineticRatio = 1e-3;
  return s;
}

TEST(RunSummary, AddsCountsKeepsTheWorstFiguresAndOrsTheFlags) {
  RunSummary t;
  t += first();
  t += second();
  EXPECT_EQ(t.steps, 15);
  EXPECT_EQ(t.iterations, 43);
  EXPECT_EQ(t.factorizations, 41);
  EXPECT_EQ(t.cuts, 4);
  EXPECT_EQ(t.hinges, 6);
  EXPECT_DOUBLE_EQ(t.energyError, 3e-9);
  // The largest gain comes with its own step and time.
  EXPECT_DOUBLE_EQ(t.energyGained, 4e-5);
  EXPECT_EQ(t.gainStep, 3);
  EXPECT_DOUBLE_EQ(t.gainTime, 0.15);
  EXPECT_DOUBLE_EQ(t.seconds, 1.75);
  EXPECT_TRUE(t.dynamic);
  EXPECT_DOUBLE_EQ(t.maxMomentRatio, 1.01);
  EXPECT_EQ(t.jointsFormed, 1);
  EXPECT_EQ(t.jointsRuptured, 2);
  EXPECT_EQ(t.fractures, 1);
  EXPECT_EQ(t.shears, 1);
  EXPECT_EQ(t.removed, 2);
  EXPECT_EQ(t.crossings, 1);
  EXPECT_EQ(t.folded, 2);
  EXPECT_EQ(t.sunk, 1);
  EXPECT_TRUE(t.memberContact);
  EXPECT_EQ(t.blastsNotMade, 1);
  EXPECT_EQ(t.debrisRuns, 2);
  EXPECT_EQ(t.outsideRuns, 1);
  EXPECT_EQ(t.movingRuns, 1);
  EXPECT_DOUBLE_EQ(t.kineticRatio, 2e-3);
  EXPECT_EQ(t.unintendedRuns, 1);
  // A later run without an unintended fall keeps the verdict of the one before.
  EXPECT_EQ(t.verdict, "backwards");
  // A smaller gain later leaves the largest one's step and time.
  RunSummary small;
  small.energyGained = 1e-6, small.gainStep = 99, small.gainTime = 9.9;
  t += small;
  EXPECT_EQ(t.gainStep, 3);
  EXPECT_DOUBLE_EQ(t.gainTime, 0.15);
}

TEST(RunSummary, TheTotalOfTwoRunsSaysHowManyOfThemLeftTheSite) {
  RunSummary t;
  t += first();
  t += second();
  const std::string text = runSummaryText(t);
  EXPECT_NE(text.find("15 steps, 43 iterations, 4 cuts, 6 hinges opened"), std::string::npos)
      << text;
  EXPECT_NE(text.find("debris OUTSIDE the site in 1 of 2 runs"), std::string::npos) << text;
  EXPECT_NE(text.find("fall NOT AS INTENDED in 1 of 2 runs"), std::string::npos) << text;
}

TEST(RunOutcome, SummaryWordsTheEnergyErrorAndWarnsWhenTheBalanceDoesNotClose) {
  RunSummary s;
  s.energyError = 2.5e-12;
  EXPECT_TRUE(contains(runSummaryText(s), "energy error 2.50e-12")) << runSummaryText(s);
  EXPECT_TRUE(runWarnings(s).empty());
  s.energyError = 0.93;
  ASSERT_EQ(runWarnings(s).size(), 1u);
  EXPECT_TRUE(contains(runWarnings(s)[0], "warning: the energy balance changed by 9.30e-01"))
      << runWarnings(s)[0];
  // Members crossing at the end: a second warning.
  s.crossings = 3;
  ASSERT_EQ(runWarnings(s).size(), 2u);
  EXPECT_TRUE(contains(runWarnings(s)[1], "warning: 3 pairs of members cross each other at the end"))
      << runWarnings(s)[1];
  // Members folded beyond a quarter turn: a third.
  s.folded = 1;
  ASSERT_EQ(runWarnings(s).size(), 3u);
  EXPECT_TRUE(contains(runWarnings(s)[2], "warning: 1 member is bent through more than a quarter"))
      << runWarnings(s)[2];
  // A node buried in the ground: a fourth.
  s.sunk = 1;
  ASSERT_EQ(runWarnings(s).size(), 4u);
  EXPECT_TRUE(
      contains(runWarnings(s)[3], "warning: in this run a node went deeper into the ground"))
      << runWarnings(s)[3];
  // A member past its capacity beyond the tolerance (macro/run/CapacityWatch.h): a fifth;
  // within it, none.
  s.maxMomentRatio = 1.0003;
  EXPECT_EQ(runWarnings(s).size(), 4u);
  s.maxMomentRatio = 1.004;
  ASSERT_EQ(runWarnings(s).size(), 5u);
  EXPECT_TRUE(contains(runWarnings(s)[2], "warning: a member carried |M|/Mu = 1.0040"))
      << runWarnings(s)[2];
}

}  // namespace
}  // namespace c2d
