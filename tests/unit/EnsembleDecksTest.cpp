// Ensembles run as decks (decks/ensemble): the sliding block against its
// closed form per drawn mu (V16), the column on a pin falling to the side it
// leans with p_outside in its Wilson interval (V17), an ensemble without draws
// giving identical runs, two plans seeing the same draws sample by sample (V18),
// and two shards merged, or `run -j 2`, giving the whole run's files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "macro/DeckRunner.h"
#include "macro/batch/Merge.h"
#include "macro/batch/ParallelRuns.h"
#include "macro/deck/DeckParser.h"
#include "macro/draws/Ensemble.h"
#include "macro/draws/Jitter.h"
#include "macro/mesh/ParseDeck.h"
#include "macro/studies/EnsembleTable.h"
#include "macro/studies/Statistics.h"
#include "tests/unit/DeckTestSupport.h"
#include "tests/unit/EnsembleTestSupport.h"
#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

namespace fs = std::filesystem;

using testing::ksStatistic;
using testing::readText;

std::string deckPath(const std::string& name) {
  return std::string(C2D_SOURCE_DIR) + "/decks/ensemble/" + name + ".inp";
}

DeckOutcome run(const std::string& name, const fs::path& out, int shard = 1, int shards = 1) {
  DeckOptions o;
  o.outDir = out;
  o.quiet = true;
  o.shard = shard;
  o.shards = shards;
  const SolutionCommands commands;
  std::ostringstream console;
  return runDeck(deckPath(name), o, commands, console);
}

EnsembleData table(const fs::path& csv, std::size_t swept) {
  return readEnsembleTable(readText(csv), swept);
}

TEST(EnsembleDecks, TheBlockParsesBeforeOrAfterTheSweep) {
  const std::string problem = "FEAP * * t\n  0 0 0 2 3 2\nEND\nBATCh\nEND\nSTOP\n";
  const std::string ens =
      "ENSEmble,,4,2\n  mu = NORMal 0.5 0.1\n  JITTer,,1e-6\n  DETOnators,PYROtechnic\n\n";
  const std::string sweep = "SWEEp\n  a = 1 2\n\n";
  for (const std::string& text : {ens + sweep + problem, sweep + ens + problem}) {
    const Deck d = parseDeckText(text, "e.inp");
    ASSERT_EQ(d.items.size(), 1u);
    const auto& sw = std::get<TopSweep>(d.items[0]);
    ASSERT_EQ(sw.body.size(), 1u);
    const auto& e = std::get<TopEnsemble>(sw.body[0]);
    EXPECT_EQ(e.draws.size(), 1u);
    EXPECT_TRUE(e.jitter && e.detonators);
    Parameters p;
    const EnsembleSpec spec = evaluateEnsemble(e, p);
    EXPECT_EQ(spec.samples, 4);
    EXPECT_EQ(spec.seed, 2u);
    EXPECT_EQ(spec.detonators->cov, DetonatorSpec::kPyrotechnicCov);
    EXPECT_EQ(spec.jitter->fdt, JitterSpec::kDefaultFdt);
  }
  using testing::expectDeckError;
  expectDeckError([&] { parseDeckText("ENSEmble\n\n" + problem, "e.inp"); }, "e.inp", 1, 9,
                  "ENSEmble needs the number of samples");
  expectDeckError([&] { parseDeckText("ENSEmble,,3\n  JITTer,ON\n\n" + problem, "e.inp"); },
                  "e.inp", 2, 10, "JITTer takes numbers only");
  expectDeckError([&] { parseDeckText("ENSEmble,,3\n  DETOnators,NONEl\n\n" + problem, "e.inp"); },
                  "e.inp", 2, 14, "unknown kind of detonator");
  expectDeckError([&] { parseDeckText("ENSEmble,,3\n  mu = UNIForm 1\n\n" + problem, "e.inp"); },
                  "e.inp", 2, 17, "'mu' needs two numbers");
  expectDeckError(
      [&] { parseDeckText("ENSEmble,,3\n  a = UNIForm 1 2\n\n" + sweep + problem, "e.inp"); },
      "e.inp", 2, 3, "'a' is both drawn and swept");
  expectDeckError([&] { parseDeckText(ens + sweep + ens + problem, "e.inp"); }, "e.inp", 9, 1,
                  "a second ENSEmble for the same problem");
  const Deck bad = parseDeckText("ENSEmble,,0\n  mu = UNIForm 2 1\n\n" + problem, "e.inp");
  Parameters p;
  expectDeckError([&] { evaluateEnsemble(std::get<TopEnsemble>(bad.items[0]), p); }, "e.inp", 1, 11,
                  "the number of samples of an ensemble is between 1");
}

// A value only some draws make bad is a deck error before anything runs, at
// its record, naming the sample and its draws.
TEST(EnsembleDecks, ADrawThatMakesTheDeckBadIsReportedWithItsSample) {
  testing::DeckTempDir dir;
  const std::string deck =
      dir.write("bad.inp",
                "ENSEmble,,20,1\n  h = NORMal 0.01 0.01\n\n"
                "FEAP * * t\n  0 0 0 2 3 2\nCOORdinates\n  1 0 0 0\n  2 0 1 0\n\n"
                "ELEMents\n  1 0 1 1 2\n\nMATErial,1\n  FRAMe\n"
                "    RESUltant STIFfness 1 1 1\n\nBOUNdary\n  1 0 1 1 1\n\nEND\n"
                "BATCh\n  DT,,h\nEND\nSTOP\n");
  const DeckOutcome r = testing::runDeckFile(dir, deck).outcome;
  EXPECT_EQ(r.exitCode, kExitDeckError);
  EXPECT_NE(r.message.find("bad.inp:22:7: error: the time step must be positive"),
            std::string::npos)
      << r.message;
  EXPECT_NE(r.message.find("(in sample "), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("of the ENSEmble of line 1, which drew h = -"), std::string::npos)
      << r.message;
  EXPECT_FALSE(fs::exists(dir.path() / "out" / "bad_ensemble.csv"));
}

// DETOnators move the prop's blast (t = 0.6) into the static step (to t = 0.5)
// in samples 1 and 3: each fails at that commit, naming the BLASt record with
// the nominal and the drawn time (it went on as a statically blasted structure
// whose failure, if any, said nothing of the blast); sample 2 runs.
TEST(EnsembleDecks, ABlastScatteredIntoAStaticStepFailsItsSampleNamingIt) {
  testing::DeckTempDir dir;
  const std::string deck = testing::sourceDeck("errors/detonators_into_statics.inp");
  const testing::DeckResult ran = testing::runDeckFile(dir, deck);
  const DeckOutcome& r = ran.outcome;
  EXPECT_EQ(r.exitCode, 2) << r.message;
  const EnsembleData data = table(ran.out / "detonators_into_statics_ensemble.csv", 0);
  ASSERT_EQ(data.runs.size(), 3u);
  for (int k : {0, 2}) {
    const std::string& why = data.runs[k].reason;
    EXPECT_FALSE(data.runs[k].ok);
    EXPECT_NE(why.find("the BLASt record " + deck +
                       ":40:3, scattered by DETOnators from t = "
                       "6.000000e-01 to t = " +
                       (k == 0 ? "2.854824e-01" : "4.204601e-01") +
                       ", falls in a static step (before DYNAmic)"),
              std::string::npos)
        << why;
  }
  EXPECT_TRUE(data.runs[1].ok) << data.runs[1].reason;
}

// Plans are compared on paired runs (sample k of every plan takes the draws of
// (seed, k)): a sample count or a seed that differs between plans (swept, or
// derived from a swept value) is refused at its field before anything runs;
// swept but equal in every plan, it is taken.
TEST(EnsembleDecks, ASampleCountOrSeedDifferingBetweenPlansIsRefused) {
  testing::DeckTempDir dir;
  const std::string problem =
      "FEAP * * t\n  0 0 0 2 3 2\nCOORdinates\n  1 0 0 0\n  2 0 1 0\n\nELEMents\n  1 0 1 1 2\n\n"
      "MATErial,1\n  FRAMe\n    RESUltant STIFfness 1 1 1\n\nBOUNdary\n  1 0 1 1 1\n\nEND\n"
      "BATCh\n  TANG,,1\nEND\nSTOP\n";
  const SolutionCommands commands;
  const std::string samples = dir.write("n.inp", "SWEEp\n  n = 2 3\n\nENSEmble,,n,1\n\n" + problem);
  testing::expectDeckError([&] { planDeck(samples, commands, {}); }, samples, 4, 11,
                           "plan 2 takes samples 3 and plan 1 2: the plans are compared on "
                           "paired runs");
  const std::string seed = dir.write(
      "s.inp", "SWEEp\n  a = 1 2\n\nPARAmeter\n  s = 7 * a\n\nENSEmble,,2,s\n\n" + problem);
  testing::expectDeckError([&] { planDeck(seed, commands, {}); }, seed, 7, 13,
                           "plan 2 takes seed 14 and plan 1 7");
  const std::string same = dir.write("e.inp", "SWEEp\n  n = 2 2\n\nENSEmble,,n,1\n\n" + problem);
  EXPECT_EQ(planDeck(same, commands, {}).runs, 4);
}

// The example ensembles (no references: minutes each) bind as decks: every
// run of their check pass, with its draws.
TEST(EnsembleDecks, TheExampleEnsemblesBind) {
  const SolutionCommands commands;
  const std::string src = std::string(C2D_SOURCE_DIR) + "/decks/";
  for (const auto& [deck, runs] : std::vector<std::pair<std::string, int>>{
           {"demolition/felling_ensemble.inp", 60},
           {"demolition/implosion_ensemble.inp", 20},
           {"collapse/six_story_demolition_ensemble.inp", 20},
           {"collapse/six_story_fall_ensemble.inp", 20},
           {"paper/six_story_collapse_ensemble.inp", 20}}) {
    const DeckPlan plan = planDeck(src + deck, commands);
    EXPECT_EQ(plan.runs, runs) << deck;
    EXPECT_TRUE(plan.study) << deck;
  }
}

// V16: right = x1 + v0^2 / (2 mu g), x1 = a g t1^2 / 2, v0 = a g t1, for its own mu.
TEST(EnsembleDecks, SlidingBlockReachesItsOwnClosedForm) {
  testing::DeckTempDir dir;
  const DeckOutcome o = run("sliding_block", dir.path());
  ASSERT_EQ(o.exitCode, 0) << o.message;
  const EnsembleData d = table(dir.path() / "sliding_block_ensemble.csv", 0);
  ASSERT_EQ(d.runs.size(), 20u);
  ASSERT_EQ(d.drawn, std::vector<std::string>{"mu"});
  const double g = 9.81, a = 0.4, t1 = 0.5, x1 = a * g * t1 * t1 / 2, v0 = a * g * t1;
  std::vector<double> mu;
  for (const EnsembleRun& r : d.runs) {
    ASSERT_TRUE(r.ok && r.debris) << r.reason;
    EXPECT_TRUE(r.atRest);
    mu.push_back(r.drawn[0]);
    EXPECT_NEAR(r.figure("right"), x1 + v0 * v0 / (2 * r.drawn[0] * g), 1e-3)
        << "mu = " << r.drawn[0];
  }
  // The drawn mu against UNIForm 0.2 0.6 (the 1 % critical value 1.628/sqrt(n)).
  EXPECT_LT(ksStatistic(mu, [](double x) { return std::clamp((x - 0.2) / 0.4, 0.0, 1.0); }),
            1.628 / std::sqrt(20.0));
}

// V17: each run falls to the side its jittered mass leans to; p_outside and its interval.
TEST(EnsembleDecks, ColumnOnAPinFallsToTheSideItLeans) {
  testing::DeckTempDir dir;
  const DeckOutcome o = run("column_on_pin", dir.path());
  ASSERT_EQ(o.exitCode, 0) << o.message;
  const EnsembleData d = table(dir.path() / "column_on_pin_ensemble.csv", 0);
  ASSERT_EQ(d.runs.size(), 20u);
  int outside = 0, right = 0;
  for (const EnsembleRun& r : d.runs) {
    ASSERT_TRUE(r.ok && r.debris) << r.reason;
    Model m;
    for (const Vec2& x : {Vec2(0, 0), Vec2(0, 0.5), Vec2(0, 1)}) m.addNode(x);
    jitterNodes(m, JitterSpec{1e-6, 0.01}, 1, r.sample);
    const double lean = 2 * (m.coord(1).x() - m.coord(0).x()) + (m.coord(2).x() - m.coord(0).x());
    EXPECT_EQ(r.outside(), lean > 0) << "sample " << r.sample;
    EXPECT_NEAR(std::max(r.figure("left"), r.figure("right")), 1, 1e-3);  // lying on the ground
    outside += r.outside();
    right += lean > 0;
  }
  EXPECT_EQ(outside, right);
  const auto plans = readText(dir.path() / "column_on_pin_plans.csv");
  const std::string row = plans.substr(plans.find('\n') + 1);
  std::vector<std::string> cells;
  std::stringstream ss(row.substr(0, row.find('\n')));
  for (std::string c; std::getline(ss, c, ',');) cells.push_back(c);
  ASSERT_GE(cells.size(), 4u);
  const double p = std::stod(cells[cells.size() - 4]), lo = std::stod(cells[cells.size() - 3]),
               hi = std::stod(cells[cells.size() - 2]);
  const auto [wlo, whi] = wilsonInterval(outside, 20);
  EXPECT_NEAR(p, outside / 20.0, 1e-6);
  EXPECT_NEAR(lo, wlo, 1e-6);
  EXPECT_NEAR(hi, whi, 1e-6);
  EXPECT_LT(lo, 0.5);
  EXPECT_GT(hi, 0.5);
  EXPECT_GT(outside, 0);
  EXPECT_LT(outside, 20);
}

TEST(EnsembleDecks, WithoutDrawsTheRunsAreIdentical) {
  testing::DeckTempDir dir;
  const DeckOutcome o = run("bar_drop_repeated", dir.path());
  ASSERT_EQ(o.exitCode, 0) << o.message;
  const std::string first = readText(dir.path() / "bar_drop_repeated_s1_tplot.csv");
  ASSERT_FALSE(first.empty());
  for (const char* k : {"2", "3"}) {
    EXPECT_EQ(readText(dir.path() / ("bar_drop_repeated_s" + std::string(k) + "_tplot.csv")),
              first);
    EXPECT_EQ(readText(dir.path() / ("bar_drop_repeated_s" + std::string(k) + "_debris.csv")),
              readText(dir.path() / "bar_drop_repeated_s1_debris.csv"));
  }
  const EnsembleData d = table(dir.path() / "bar_drop_repeated_ensemble.csv", 0);
  ASSERT_EQ(d.runs.size(), 3u);
  EXPECT_TRUE(d.drawn.empty());
  for (const EnsembleRun& r : d.runs) EXPECT_EQ(r.figures, d.runs[0].figures);
}

// V18: plan a = 0.3 and plan a = 0.4 see the same mu and time-step factor in
// sample k, and each run reaches its closed form.
TEST(EnsembleDecks, PlansSeeTheSameDrawsSampleBySample) {
  testing::DeckTempDir dir;
  const DeckOutcome o = run("sliding_plans", dir.path());
  ASSERT_EQ(o.exitCode, 0) << o.message;
  const EnsembleData d = table(dir.path() / "sliding_plans_ensemble.csv", 1);
  ASSERT_EQ(d.runs.size(), 12u);
  ASSERT_EQ(d.drawn, (std::vector<std::string>{"mu", "dt_factor"}));
  const double g = 9.81, t1 = 0.5;
  for (int k = 0; k < 6; ++k) {
    const EnsembleRun& p1 = d.runs[static_cast<std::size_t>(k)];
    const EnsembleRun& p2 = d.runs[static_cast<std::size_t>(k + 6)];
    ASSERT_EQ(p1.plan, 1);
    ASSERT_EQ(p2.plan, 2);
    ASSERT_EQ(p1.sample, p2.sample);
    EXPECT_EQ(p1.drawn, p2.drawn);
    for (const EnsembleRun* r : {&p1, &p2}) {
      // JITTer scales the steps: the incline lasts 500 steps of dt_factor 1 ms.
      const double t = t1 * r->drawn[1], a = r->swept[0], x1 = a * g * t * t / 2, v0 = a * g * t;
      EXPECT_NEAR(r->figure("right"), x1 + v0 * v0 / (2 * r->drawn[0] * g), 1e-3);
    }
    EXPECT_LT(p1.figure("right"), p2.figure("right"));
  }
  const std::string log = readText(dir.path() / "sliding_plans.out");
  EXPECT_NE(log.find("best plan: 1 (a = 0.3)"), std::string::npos);
  EXPECT_NE(log.find(": significant"), std::string::npos);
}

// The run,plan,sample cells of a timing table, one line per run.
std::string timingKeys(const fs::path& csv) {
  std::istringstream in(readText(csv));
  std::string line, keys;
  while (std::getline(in, line)) keys += line.substr(0, line.rfind(',')) + "\n";
  return keys;
}

// The files of a study one process writes.
const std::vector<std::string> kStudyFiles = {
    "sliding_plans_ensemble.csv", "sliding_plans_plans.csv", "sliding_plans_sensitivity.csv",
    "sliding_plans_ensemble.svg", "sliding_plans_disp_2_1_vs_time.svg"};

TEST(EnsembleDecks, TwoShardsMergedEqualTheWholeRun) {
  testing::DeckTempDir dir;
  ASSERT_EQ(run("sliding_plans", dir.path() / "whole").exitCode, 0);
  for (int i = 1; i <= 2; ++i) {
    const DeckOutcome o = run("sliding_plans", dir.path() / "parts", i, 2);
    ASSERT_EQ(o.exitCode, 0) << o.message;
    EXPECT_EQ(o.runs, 6);
  }
  EXPECT_FALSE(fs::exists(dir.path() / "parts" / "sliding_plans_plans.csv"));
  std::ostringstream out, err;
  ASSERT_EQ(mergeParts(dir.path() / "parts", out, err), 0) << err.str();
  for (const std::string& f : kStudyFiles) {
    ASSERT_TRUE(fs::exists(dir.path() / "parts" / f)) << f;
    EXPECT_EQ(readText(dir.path() / "parts" / f), readText(dir.path() / "whole" / f)) << f;
  }
  // The runs' numerics are in the table (the same bytes); their CPU times,
  // which differ, beside it, in the same runs' order.
  const EnsembleData whole = table(dir.path() / "whole" / "sliding_plans_ensemble.csv", 1);
  ASSERT_EQ(whole.runs.size(), 12u);
  for (const EnsembleRun& r : whole.runs) {
    EXPECT_GT(r.numerics.steps, 0) << r.run;
    EXPECT_GE(r.numerics.iterations, r.numerics.steps) << r.run;
  }
  EXPECT_EQ(timingKeys(dir.path() / "parts" / "sliding_plans_timing.csv"),
            timingKeys(dir.path() / "whole" / "sliding_plans_timing.csv"));
  EXPECT_NE(out.str().find("best plan: 1 (a = 0.3)"), std::string::npos) << out.str();
}

TEST(EnsembleDecks, RunInTwoProcessesEqualsTheWholeRun) {
  testing::DeckTempDir dir;
  ASSERT_EQ(run("sliding_plans", dir.path() / "whole").exitCode, 0);
  BatchOptions b;
  b.deck.outDir = dir.path() / "j2";
  b.deck.quiet = true;
  b.jobs = 2;
  const SolutionCommands commands;
  std::ostringstream out, err;
  ASSERT_EQ(runDeckInParallel(deckPath("sliding_plans"), b, deckCalls(commands), out, err), 0) << err.str();
  for (const std::string& f : kStudyFiles)
    EXPECT_EQ(readText(dir.path() / "j2" / f), readText(dir.path() / "whole" / f)) << f;
  // The parts are merged and gone; the log holds every run in order.
  EXPECT_FALSE(fs::exists(dir.path() / "j2" / "sliding_plans_part1of2.out"));
  EXPECT_FALSE(fs::exists(dir.path() / "j2" / "sliding_plans_part2of2_ensemble.csv"));
  EXPECT_FALSE(fs::exists(dir.path() / "j2" / "sliding_plans_part2of2_timing.csv"));
  EXPECT_EQ(timingKeys(dir.path() / "j2" / "sliding_plans_timing.csv"),
            timingKeys(dir.path() / "whole" / "sliding_plans_timing.csv"));
  const std::string log = readText(dir.path() / "j2" / "sliding_plans.out");
  std::size_t at = 0;
  for (int k = 1; k <= 12; ++k) {
    const std::size_t p = log.find("  run " + std::to_string(k) + " of 12,", at);
    ASSERT_NE(p, std::string::npos) << "run " << k;
    at = p;
  }
  EXPECT_NE(log.find("best plan: 1 (a = 0.3)", at), std::string::npos);
}

}  // namespace
}  // namespace c2d
