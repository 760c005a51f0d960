// Studies split over machines (macro/batch/Shard): the --shard argument, which decks
// or runs a part takes, the batch table as CSV, and merge joining the parts of
// a study back into one plans table (and refusing an incomplete set).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "macro/DeckRunner.h"
#include "macro/batch/Shard.h"
#include "macro/batch/Merge.h"
#include "tests/unit/DeckTestSupport.h"

namespace c2d {
namespace {

using testing::readText;

TEST(Shard, ParseAndSelect) {
  ShardSpec s;
  EXPECT_TRUE(parseShard("2/3", s));
  EXPECT_EQ(s.index, 2);
  EXPECT_EQ(s.count, 3);
  EXPECT_EQ(s.tag(), "part2of3");
  ShardSpec bad;
  for (const char* t : {"0/3", "4/3", "2", "2/", "a/b", "2/3x", "-1/2"})
    EXPECT_FALSE(parseShard(t, bad)) << t;

  DeckOptions o;
  const std::vector<std::string> decks{"a", "b", "c", "d", "e"};
  EXPECT_EQ(shardDecks(decks, s, o), (std::vector<std::string>{"b", "e"}));  // k mod 3 == 1
  EXPECT_EQ(o.shards, 1);
  EXPECT_EQ(shardDecks({"one"}, s, o), (std::vector<std::string>{"one"}));
  EXPECT_EQ(o.shard, 2);
  EXPECT_EQ(o.shards, 3);
}

TEST(Shard, BatchCsvRoundTrip) {
  BatchResult a;
  a.started = true;
  a.deck = "dir,with comma/a.inp";
  a.runs = 3;
  a.steps = 10;
  a.iterations = 25;
  a.seconds = 1.5;
  a.debrisRuns = 3;
  a.outsideRuns = 1;
  BatchResult b;
  b.started = true;
  b.deck = "b.inp";
  b.exitCode = kExitAnalysisFailed;
  const auto back = readBatchCsv(batchCsv({a, b}));
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].deck, a.deck);
  EXPECT_EQ(back[0].iterations, 25);
  EXPECT_EQ(back[0].outsideRuns, 1);
  EXPECT_DOUBLE_EQ(back[0].seconds, 1.5);
  EXPECT_EQ(back[1].status(), "analysis failed");
}

// The study of decks/output/plan_study.inp in two parts: part 1 runs plans 1
// and 3 (the failing one), part 2 plan 2; merged, the table is the unsplit one.
TEST(Shard, PartsOfAStudyMergeIntoOneTable) {
  testing::DeckTempDir dir;
  const std::string deck = std::string(C2D_SOURCE_DIR) + "/decks/output/plan_study.inp";
  const SolutionCommands commands;
  std::ostringstream console;
  DeckOptions whole;
  whole.outDir = dir.path() / "whole";
  whole.quiet = true;
  EXPECT_EQ(runDeck(deck, whole, commands, console).exitCode, kExitAnalysisFailed);

  DeckOptions part = whole;
  part.outDir = dir.path() / "parts";
  part.shards = 2;
  std::vector<BatchResult> results;
  for (int i = 1; i <= 2; ++i) {
    part.shard = i;
    const DeckOutcome o = runDeck(deck, part, commands, console);
    EXPECT_EQ(o.runs, i == 1 ? 2 : 1);
    EXPECT_EQ(o.exitCode, i == 1 ? kExitAnalysisFailed : kExitOk) << o.message;
    EXPECT_TRUE(
        std::filesystem::exists(part.outDir / ("plan_study_part" + std::to_string(i) + "of2.out")));
    BatchResult r;
    r.deck = deck;
    r.exitCode = o.exitCode;
    r.runs = o.runs;
    writeBatchPart(part.outDir, ShardSpec{i, 2}, {r});
    if (i == 1) {
      // One part alone is an incomplete set.
      std::ostringstream out, err;
      EXPECT_EQ(mergeParts(part.outDir, out, err), 1);
      EXPECT_NE(err.str().find("part 2 of 2 missing"), std::string::npos) << err.str();
    }
  }
  std::ostringstream out, err;
  EXPECT_EQ(mergeParts(part.outDir, out, err), 0) << err.str();
  EXPECT_EQ(readText(part.outDir / "plan_study_plans.csv"),
            readText(whole.outDir / "plan_study_plans.csv"));
  EXPECT_NE(out.str().find("3 plans from 2 parts, 1 failed"), std::string::npos) << out.str();
  const auto merged = readBatchCsv(readText(part.outDir / "batch.csv"));
  ASSERT_EQ(merged.size(), 1u);
  EXPECT_EQ(merged[0].runs, 3);
  EXPECT_EQ(merged[0].exitCode, kExitAnalysisFailed);
}

TEST(Shard, CountsAreRangeChecked) {
  ShardSpec s;
  EXPECT_TRUE(parseShard("2/4", s));
  EXPECT_EQ(s.index, 2);
  EXPECT_EQ(s.count, 4);
  for (const char* bad : {"1/99999999999", "1/10001", "0/2", "3/2", "1/2x", "1/", "/2", "-1/2",
                          "1/-2", "99999999999/2", " 1/2"})
    EXPECT_FALSE(parseShard(bad, s)) << bad;
}

}  // namespace
}  // namespace c2d
