// What an ensemble writes per run: the table's steps, iterations, cuts and
// energy_error are the run's own summary (the log's line), and the bytes a
// run's outputs take put a study of 3 plans x 200 samples (600 runs, the
// reference's Slurm example) well below 100 MB (tests/bench/README.md has the
// figures of a demolition deck).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <regex>
#include <sstream>

#include "macro/DeckRunner.h"
#include "macro/studies/EnsembleTable.h"
#include "tests/unit/DeckTestSupport.h"
#include "tests/unit/StudyBytes.h"

namespace c2d {
namespace {

namespace fs = std::filesystem;

using testing::readText;

// decks/ensemble/sliding_plans (2 plans x 6 samples), run once for these tests.
const fs::path& study() {
  static testing::DeckTempDir dir;
  static const bool ran = [] {
    DeckOptions o;
    o.outDir = dir.path();
    o.quiet = true;
    const SolutionCommands commands;
    std::ostringstream console;
    return runDeck(std::string(C2D_SOURCE_DIR) + "/decks/ensemble/sliding_plans.inp", o, commands,
                   console)
               .exitCode == 0;
  }();
  EXPECT_TRUE(ran);
  return dir.path();
}

TEST(EnsembleOutputs, EveryRunsNumericsAreItsSummary) {
  const EnsembleData d = readEnsembleTable(readText(study() / "sliding_plans_ensemble.csv"), 1);
  ASSERT_EQ(d.runs.size(), 12u);
  const std::string log = readText(study() / "sliding_plans.out");
  const std::regex summary(
      R"(summary: (\d+) steps?, (\d+) iterations?, (\d+) cuts?,[^\n]*energy error ([-+.e0-9]+))");
  std::size_t k = 0;
  for (auto it = std::sregex_iterator(log.begin(), log.end(), summary);
       it != std::sregex_iterator(); ++it, ++k) {
    ASSERT_LT(k, d.runs.size());
    const RunNumerics& n = d.runs[k].numerics;
    EXPECT_EQ(n.steps, std::stoi((*it)[1])) << "run " << d.runs[k].run;
    EXPECT_EQ(n.iterations, std::stoi((*it)[2])) << "run " << d.runs[k].run;
    EXPECT_EQ(n.cuts, std::stoi((*it)[3])) << "run " << d.runs[k].run;
    const double e = std::stod((*it)[4]);  // 3 digits in the log and the table
    EXPECT_NEAR(n.energyError, e, 0.01 * e) << "run " << d.runs[k].run;
    EXPECT_GT(n.steps, 100);  // a dynamic slide of a second at dt = 1e-3 or so
  }
  EXPECT_EQ(k, d.runs.size());
}

TEST(EnsembleOutputs, SixHundredRunsWriteLessThanAHundredMegabytes) {
  const testing::StudyBytes b = testing::studyBytes(study(), "sliding_plans");
  ASSERT_EQ(b.run.size(), 12u);
  ASSERT_EQ(b.plans, 2);
  // 3 plans x 200 samples: 3 first samples, 597 others, the study's files per plan.
  const double total = b.study(3, 200);
  std::cout << "  bytes: a plan's first sample " << b.first << ", another sample " << b.other
            << ", the study's files " << b.shared << " (2 plans); 600 runs: " << total * 1e-6
            << " MB\n";
  EXPECT_GT(b.other, 1000);           // its time history, debris row, log section, table rows
  EXPECT_LT(b.other, 0.1 * b.first);  // a short log, no pictures
  EXPECT_LT(total, 100e6);
}

}  // namespace
}  // namespace c2d
