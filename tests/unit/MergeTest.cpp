// collapse2d merge refuses a bad part by name and writes nothing for its set:
// a part cut in the middle of a row, missing its last row, empty, copied over
// another, written by another deck with the same stem, with text in a number
// column; a full disk is an I/O error (status 3), not an abort.
#include <gtest/gtest.h>

#include <cerrno>
#include <fstream>
#include <functional>
#include <sstream>

#include "core/io/AtomicFile.h"
#include "macro/DeckRunner.h"
#include "macro/batch/Shard.h"
#include "macro/batch/Merge.h"
#include "tests/unit/DeckTestSupport.h"

namespace c2d {
namespace {

namespace fs = std::filesystem;

using testing::readText;

void spit(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

// The two parts of a deck's study in dir/parts (and the batch parts).
void runParts(const std::string& deck, const fs::path& dir) {
  const SolutionCommands commands;
  std::ostringstream console;
  DeckOptions o;
  o.outDir = dir;
  o.quiet = true;
  o.shards = 2;
  for (int i = 1; i <= 2; ++i) {
    o.shard = i;
    const DeckOutcome r = runDeck(deck, o, commands, console);
    ASSERT_TRUE(r.exitCode == 0 || r.exitCode == kExitAnalysisFailed) << r.message;
    BatchResult b;
    b.deck = deck;
    b.started = true;
    b.exitCode = r.exitCode;
    b.runs = r.runs;
    writeBatchPart(dir, ShardSpec{i, 2}, {b});
  }
}

const std::string kPlanDeck = std::string(C2D_SOURCE_DIR) + "/decks/output/plan_study.inp";

// A merge of the damaged parts: refused (status 1), the message names `file`
// and says `why`, and the set's joined table is not written.
void expectRefused(const std::function<void(const fs::path&)>& damage, const std::string& file,
                   const std::string& why, const std::string& joined = "plan_study_plans.csv") {
  testing::DeckTempDir dir;
  runParts(kPlanDeck, dir.path());
  damage(dir.path());
  std::ostringstream out, err;
  EXPECT_EQ(mergeParts(dir.path(), out, err), 1) << out.str();
  EXPECT_NE(err.str().find(file), std::string::npos) << err.str();
  EXPECT_NE(err.str().find(why), std::string::npos) << err.str();
  EXPECT_NE(err.str().find("not merged"), std::string::npos) << err.str();
  EXPECT_FALSE(fs::exists(dir.path() / joined));
}

TEST(Merge, TheGoodPartsMerge) {
  testing::DeckTempDir dir;
  runParts(kPlanDeck, dir.path());
  std::ostringstream out, err;
  EXPECT_EQ(mergeParts(dir.path(), out, err), 0) << err.str();
  EXPECT_NE(out.str().find("3 plans from 2 parts, 1 failed"), std::string::npos) << out.str();
}

TEST(Merge, RefusesAPartCutInTheMiddleOfARow) {
  expectRefused(
      [](const fs::path& d) {
        const fs::path f = d / "plan_study_part1of2_plans.csv";
        const std::string t = readText(f);
        spit(f, t.substr(0, t.size() - 9));
      },
      "plan_study_part1of2_plans.csv", "ends in the middle of a row");
}

TEST(Merge, RefusesAPartMissingItsLastRow) {
  expectRefused(
      [](const fs::path& d) {
        const fs::path f = d / "plan_study_part1of2_plans.csv";
        std::string t = readText(f);
        t.pop_back();
        spit(f, t.substr(0, t.rfind('\n') + 1));
      },
      "plan_study_part1of2_plans.csv",
      "holds runs 1 (1 run), where part 1 of 2 of this deck (3 runs) holds runs 1, 3");
}

TEST(Merge, RefusesAnEmptyPart) {
  expectRefused([](const fs::path& d) { spit(d / "plan_study_part2of2_plans.csv", ""); },
                "plan_study_part2of2_plans.csv", "it is empty");
}

TEST(Merge, RefusesPartOneCopiedOverPartTwo) {
  expectRefused(
      [](const fs::path& d) {
        fs::copy_file(d / "plan_study_part1of2_plans.csv", d / "plan_study_part2of2_plans.csv",
                      fs::copy_options::overwrite_existing);
      },
      "plan_study_part2of2_plans.csv", "holds runs 1, 3 (2 runs), where part 2 of 2");
  // The manifest copied too says which part it is.
  expectRefused(
      [](const fs::path& d) {
        for (const char* f : {"_manifest.csv", "_plans.csv"})
          fs::copy_file(d / (std::string("plan_study_part1of2") + f),
                        d / (std::string("plan_study_part2of2") + f),
                        fs::copy_options::overwrite_existing);
      },
      "plan_study_part2of2_manifest.csv", "it says part 1 of 2");
}

TEST(Merge, RefusesAPartOfAnotherDeckWithTheSameStem) {
  expectRefused(
      [](const fs::path& d) {
        // The same study with other plans, in another directory, same file name.
        testing::DeckTempDir other;
        std::string text = readText(kPlanDeck);
        text.replace(text.find("dx = 0.5 1.5 3"), 14, "dx = 0.5 2.5 3");
        const std::string deck = other.write("plan_study.inp", text);
        const SolutionCommands commands;
        std::ostringstream console;
        DeckOptions o;
        o.outDir = d;
        o.quiet = true;
        o.shard = 2;
        o.shards = 2;
        runDeck(deck, o, commands, console);
      },
      "plan_study_part2of2_manifest.csv", "written by another deck than part 1");
}

TEST(Merge, RefusesTextInANumberColumn) {
  expectRefused(
      [](const fs::path& d) {
        const fs::path f = d / "plan_study_part2of2_plans.csv";
        std::string t = readText(f);
        const std::size_t row = t.find('\n') + 1;
        const std::size_t cell = t.find("1.500000e+00", row);  // right = 1.5 (plan dx = 1.5)
        ASSERT_NE(cell, std::string::npos) << t;
        t.replace(cell, 12, "1.5 m");
        spit(f, t);
      },
      "plan_study_part2of2_plans.csv", "'1.5 m' in column right is not a number");
}

TEST(Merge, RefusesABadBatchPart) {
  testing::DeckTempDir dir;
  runParts(kPlanDeck, dir.path());
  const fs::path f = dir.path() / "batch_part2of2.csv";
  std::string t = readText(f);
  t.replace(t.rfind(",0,0\n"), 5, ",0,x\n");
  spit(f, t);
  std::ostringstream out, err;
  EXPECT_EQ(mergeParts(dir.path(), out, err), 1);
  EXPECT_NE(err.str().find(
                "batch_part2of2.csv: line 2: 'x' in column outside_runs is not a whole number"),
            std::string::npos)
      << err.str();
  EXPECT_FALSE(fs::exists(dir.path() / "batch.csv"));
  // The study itself merges.
  EXPECT_TRUE(fs::exists(dir.path() / "plan_study_plans.csv"));
}

TEST(Merge, AFullDiskIsAnIoError) {
  testing::DeckTempDir dir;
  runParts(kPlanDeck, dir.path());
  const SimulatedWriteFailure full("plan_study_plans.csv", ENOSPC);
  std::ostringstream out, err;
  EXPECT_EQ(mergeParts(dir.path(), out, err), kExitInternal);
  EXPECT_NE(err.str().find("I/O error"), std::string::npos) << err.str();
  EXPECT_NE(err.str().find("cannot write"), std::string::npos) << err.str();
  EXPECT_NE(err.str().find("plan_study_plans.csv'"), std::string::npos) << err.str();
}

TEST(Merge, RefusesABadEnsemblePart) {
  testing::DeckTempDir dir;
  runParts(std::string(C2D_SOURCE_DIR) + "/decks/ensemble/sliding_plans.inp", dir.path());
  const fs::path f = dir.path() / "sliding_plans_part2of2_ensemble.csv";
  std::string t = readText(f);
  t.replace(t.find(",ok,"), 4, ",OK,");
  spit(f, t);
  std::ostringstream out, err;
  EXPECT_EQ(mergeParts(dir.path(), out, err), 1);
  EXPECT_NE(err.str().find(
                "sliding_plans_part2of2_ensemble.csv: line 2, column status: the status is 'OK'"),
            std::string::npos)
      << err.str();
  EXPECT_FALSE(fs::exists(dir.path() / "sliding_plans_plans.csv"));
  // The curves of the overlay are a part's file too.
  t.replace(t.find(",OK,"), 4, ",ok,");
  spit(f, t);
  fs::remove(dir.path() / "sliding_plans_part1of2_curves.csv");
  std::ostringstream out2, err2;
  EXPECT_EQ(mergeParts(dir.path(), out2, err2), 1);
  EXPECT_NE(err2.str().find("sliding_plans_part1of2_curves.csv: missing"), std::string::npos)
      << err2.str();
}

// The parts' CPU times join by run into <stem>_timing.csv, beside the ensemble
// table; a timing part whose runs are not its table's is refused by name, and
// without every part's times none are joined (and merge says so).
TEST(Merge, JoinsThePartsCpuTimesByRun) {
  testing::DeckTempDir dir;
  runParts(std::string(C2D_SOURCE_DIR) + "/decks/ensemble/sliding_plans.inp", dir.path());
  const fs::path f = dir.path() / "sliding_plans_part2of2_timing.csv";
  const std::string good = readText(f);
  {
    std::ostringstream out, err;
    ASSERT_EQ(mergeParts(dir.path(), out, err), 0) << err.str();
    std::istringstream in(readText(dir.path() / "sliding_plans_timing.csv"));
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "run,plan,sample,cpu_s");
    for (int run = 1; run <= 12; ++run) {
      ASSERT_TRUE(std::getline(in, line)) << run;
      const int plan = (run - 1) / 6 + 1, sample = (run - 1) % 6 + 1;
      EXPECT_EQ(line.rfind(std::to_string(run) + "," + std::to_string(plan) + "," +
                               std::to_string(sample) + ",",
                           0),
                0u)
          << line;
    }
    EXPECT_FALSE(std::getline(in, line));
  }
  fs::remove(dir.path() / "sliding_plans_timing.csv");
  fs::remove(dir.path() / "sliding_plans_ensemble.csv");
  spit(f, good.substr(0, good.rfind('\n', good.size() - 2) + 1));  // its last run dropped
  {
    std::ostringstream out, err;
    EXPECT_EQ(mergeParts(dir.path(), out, err), 1);
    EXPECT_NE(err.str().find("sliding_plans_part2of2_timing.csv: it holds runs 2, 4, 6, 8, 10 (5 "
                             "runs), where its ensemble table holds runs 2, 4, 6, 8, 10, 12 (6 "
                             "runs)"),
              std::string::npos)
        << err.str();
    EXPECT_FALSE(fs::exists(dir.path() / "sliding_plans_ensemble.csv"));
  }
  fs::remove(f);
  {
    std::ostringstream out, err;
    EXPECT_EQ(mergeParts(dir.path(), out, err), 0) << err.str();
    EXPECT_NE(out.str().find("sliding_plans_timing.csv not written: 1 of 2 parts have their CPU "
                             "times"),
              std::string::npos)
        << out.str();
    EXPECT_FALSE(fs::exists(dir.path() / "sliding_plans_timing.csv"));
  }
}

// The names of stray files give counts out of range (a part count beyond the
// limit, or 0): each is refused by name, nothing is read or written for it.
TEST(Merge, RefusesPartCountsOutOfRangeInFileNames) {
  testing::DeckTempDir dir;
  for (const char* name : {"x_part1of99999999999_manifest.csv", "batch_part1of99999999999.csv",
                           "x_part1of0_plans.csv", "y_part1of200000000_manifest.csv",
                           "batch_part3of2.csv"})
    spit(dir.path() / name, "key,value\n");
  std::ostringstream out, err;
  EXPECT_EQ(mergeParts(dir.path(), out, err), 1) << out.str();
  for (const char* name : {"x_part1of99999999999_manifest.csv", "batch_part1of99999999999.csv",
                           "x_part1of0_plans.csv", "y_part1of200000000_manifest.csv",
                           "batch_part3of2.csv"})
    EXPECT_NE(err.str().find(std::string(name) + ": its name says part"), std::string::npos)
        << name << "\n" << err.str();
  EXPECT_FALSE(fs::exists(dir.path() / "x_.csv"));
  EXPECT_FALSE(fs::exists(dir.path() / "batch.csv"));
}

TEST(Merge, RefusesACountOutOfRangeInAManifest) {
  expectRefused(
      [](const fs::path& d) {
        const fs::path f = d / "plan_study_part2of2_manifest.csv";
        std::string t = readText(f);
        t.replace(t.find("runs,3"), 6, "runs,2147483647");
        spit(f, t);
      },
      "plan_study_part2of2_manifest.csv",
      "the manifest's runs '2147483647' is not a whole number from 1 to 10000");
}

TEST(Merge, RefusesAPartThatIsNotARegularFile) {
  expectRefused(
      [](const fs::path& d) {
        const fs::path f = d / "plan_study_part2of2_plans.csv";
        fs::remove(f);
        fs::create_symlink("/dev/zero", f);
      },
      "plan_study_part2of2_plans.csv", "it is not a regular file");
}

TEST(Merge, RefusesAnInfiniteFigureInAnEnsemblePart) {
  testing::DeckTempDir dir;
  runParts(std::string(C2D_SOURCE_DIR) + "/decks/ensemble/sliding_plans.inp", dir.path());
  const fs::path f = dir.path() / "sliding_plans_part2of2_ensemble.csv";
  std::string t = readText(f);
  const std::size_t row = t.find('\n') + 1;
  const std::size_t ok = t.find(",ok,", row);
  std::size_t cell = ok + 4;  // the reason, then steps, iterations, cuts, energy_error
  for (int k = 0; k < 5; ++k) cell = t.find(',', cell) + 1;  // the first debris figure
  t.replace(cell, t.find(',', cell) - cell, "inf");
  spit(f, t);
  std::ostringstream out, err;
  EXPECT_EQ(mergeParts(dir.path(), out, err), 1);
  EXPECT_NE(err.str().find("sliding_plans_part2of2_ensemble.csv: line 2, column"),
            std::string::npos)
      << err.str();
  EXPECT_NE(err.str().find("'inf' is not a number"), std::string::npos) << err.str();
  EXPECT_FALSE(fs::exists(dir.path() / "sliding_plans_ensemble.csv"));
}

// A table that parses and holds the right runs, but is not the one its part
// wrote (a plans table of another deck with the same stem and run count).
TEST(Merge, RefusesATableItsManifestDidNotRecord) {
  expectRefused(
      [](const fs::path& d) {
        const fs::path f = d / "plan_study_part2of2_plans.csv";
        std::string t = readText(f);
        const std::size_t cell = t.find("1.500000e+00", t.find('\n') + 1);
        ASSERT_NE(cell, std::string::npos) << t;
        t.replace(cell, 12, "1.600000e+00");
        spit(f, t);
      },
      "plan_study_part2of2_plans.csv", "its text is not the one its part wrote");
}

TEST(Merge, RefusesCurvesThatLostRows) {
  testing::DeckTempDir dir;
  runParts(std::string(C2D_SOURCE_DIR) + "/decks/ensemble/sliding_plans.inp", dir.path());
  const fs::path f = dir.path() / "sliding_plans_part1of2_curves.csv";
  std::string t = readText(f);
  t.pop_back();
  spit(f, t.substr(0, t.rfind('\n') + 1));
  std::ostringstream out, err;
  EXPECT_EQ(mergeParts(dir.path(), out, err), 1);
  EXPECT_NE(err.str().find("sliding_plans_part1of2_curves.csv: its text is not the one"),
            std::string::npos)
      << err.str();
}

// An ensemble row whose plan disagrees with its run number (its manifest
// rewritten to match): refused in the part that holds it.
TEST(Merge, RefusesAnEnsembleRowWhosePlanDisagreesWithItsRun) {
  testing::DeckTempDir dir;
  runParts(std::string(C2D_SOURCE_DIR) + "/decks/ensemble/sliding_plans.inp", dir.path());
  const fs::path f = dir.path() / "sliding_plans_part2of2_ensemble.csv";
  std::string t = readText(f);
  const std::size_t row = t.find('\n') + 1;  // run 2: plan 1, sample 2
  ASSERT_EQ(t.substr(row, 6), "2,1,2,") << t;
  t.replace(row, 6, "2,2,2,");
  spit(f, t);
  const fs::path m = dir.path() / "sliding_plans_part2of2_manifest.csv";
  std::string mt = readText(m);
  const std::size_t h = mt.find("table_hash,") + 11;
  mt.replace(h, 16, contentFingerprint(t));
  spit(m, mt);
  std::ostringstream out, err;
  EXPECT_EQ(mergeParts(dir.path(), out, err), 1);
  EXPECT_NE(err.str().find("sliding_plans_part2of2_ensemble.csv: line of run 2: plan 2, sample 2 "
                           "does not follow plan 1, sample 1"),
            std::string::npos)
      << err.str();
  EXPECT_FALSE(fs::exists(dir.path() / "sliding_plans_ensemble.csv"));
}

// Parts of one stem split in 2 and in 3 (before and after an edit) would write
// the same tables: neither set is merged.
TEST(Merge, RefusesTwoPartSetsOfOneStem) {
  testing::DeckTempDir dir;
  runParts(kPlanDeck, dir.path());
  const SolutionCommands commands;
  std::ostringstream console;
  DeckOptions o;
  o.outDir = dir.path();
  o.quiet = true;
  o.shards = 3;
  for (int i = 1; i <= 3; ++i) {
    o.shard = i;
    runDeck(kPlanDeck, o, commands, console);
  }
  std::ostringstream out, err;
  EXPECT_EQ(mergeParts(dir.path(), out, err), 1);
  EXPECT_NE(err.str().find("plan_study_part<i>of2: the folder holds parts of plan_study in 3 too"),
            std::string::npos)
      << err.str();
  EXPECT_NE(err.str().find("plan_study_part<i>of3: the folder holds parts of plan_study in 2 too"),
            std::string::npos)
      << err.str();
  EXPECT_FALSE(fs::exists(dir.path() / "plan_study_plans.csv"));
}

}  // namespace
}  // namespace c2d
