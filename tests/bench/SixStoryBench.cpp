// The paper's six-story frame, 288 elements:
//  - SixStoryWorkflow: decks/paper/six_story_collapse.inp: the failure phase
//    until the hinges have formed, HINGE2JOINT, the collapse phase with ground
//    contact and gravity until the frame lies on the ground;
//  - SixStoryStatic: the static failure analysis to the full mechanism
//    (decks/paper/six_story_static_meshes.inp, its 288-element run only);
//  - SixStoryDemolition: the main example, decks/collapse/six_story_demolition.inp
//    (pushed to its mechanism, HINGe2joint,INELastic, released, falls onto a
//    crushing ground with friction; target 2 s on the 2-core test machine);
//  - SixStoryDemolitionMemberContact: the main example run twice back to
//    back, with ground contact only (kmem = 0) and as shipped with member
//    contact (kmem = 1e5), with the ratio of their CPU times (target: at most 1.5)
//    and each run's steps, iterations, cuts, factorizations and CPU time per
//    iteration (counters suffixed _ground and _members);
//  - SixStoryDemolitionMemberContactEnsemble: the same over the main example's
//    ensemble (decks/collapse/six_story_demolition_ensemble.inp) cut to six
//    jittered samples, their CPU times summed (sample by sample, each
//    without and then with member contact). One history's ratio is itself
//    a sample: the jittered runs of one deck spread by 10-20 % in steps and
//    iterations, and the unjittered main example's ground-only run is among
//    the shortest of its ensemble.
// Counters: steps, Newton iterations, factorizations, seconds per iteration.
// Run: build/tests/benchmarks --benchmark_filter=SixStory
#include <benchmark/benchmark.h>

#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/bench/DeckBench.h"

namespace {

using c2d::DeckOptions;
using c2d::DeckOutcome;
using c2d::SolutionCommands;
using c2d::bench::runDeck;

std::filesystem::path paperDeck(const char* name) { return c2d::bench::sourceDeck("paper", name); }

void BM_SixStoryWorkflow(benchmark::State& st) { runDeck(st, paperDeck("six_story_collapse.inp")); }

void BM_SixStoryDemolition(benchmark::State& st) {
  runDeck(st, c2d::bench::sourceDeck("collapse", "six_story_demolition.inp"));
}

// The main example (or its ensemble, name) as a copy whose member contact
// stiffness is kmem, whose ENSEmble has `samples` samples (0: as it is) and
// whose include is named by absolute path (the copy lives in a scratch
// directory); empty when the source deck is not found (the decks are found
// from the source file's path as the compiler gave it, which may be relative
// to the build directory).
std::filesystem::path demolitionDeck(const std::string& kmem,
                                     const char* name = "six_story_demolition.inp",
                                     int samples = 0) {
  const std::filesystem::path source =
      std::filesystem::absolute(c2d::bench::sourceDeck("collapse", name));
  if (!std::filesystem::exists(source)) return {};
  std::ifstream in(source);
  std::stringstream text;
  text << in.rdbuf();
  std::string deck = text.str();
  auto replaceLine = [&](const std::string& start, const std::string& by) {
    const auto at = deck.find(start);
    if (at == std::string::npos) return;
    deck.replace(at, deck.find('\n', at) - at, by);
  };
  replaceLine("  kmem = ", "  kmem = " + kmem);
  if (samples > 0) replaceLine("ENSEmble,,", "ENSEmble,," + std::to_string(samples) + ",1");
  replaceLine("INCLude,six_story_fall.inc",
              "INCLude," + (source.parent_path() / "six_story_fall.inc").string());
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() /
      ("c2d_bench_kmem_" + kmem + (samples > 0 ? "_ensemble" : ""));
  std::filesystem::create_directories(dir);
  const std::filesystem::path copy = dir / "six_story_demolition.inp";
  std::ofstream(copy) << deck;
  return copy;
}

// The deck without and with member contact, back to back: the ratio of their
// CPU times and each one's counters. An ensemble's samples are run one at a
// time (shards), each without and then with member contact, so that a slow
// stretch of a shared machine weighs on both alike.
void memberContactRatio(benchmark::State& st, const char* name, int samples) {
  SolutionCommands commands;
  const char* kmem[2] = {"0", "1e5"};
  const int parts = samples > 0 ? samples : 1;
  double seconds[2] = {0, 0}, steps[2] = {0, 0}, iterations[2] = {0, 0}, cuts[2] = {0, 0},
         factorizations[2] = {0, 0};
  for (auto _ : st) {
    for (int part = 1; part <= parts; ++part)
      for (int k = 0; k < 2; ++k) {
        const std::filesystem::path deck = demolitionDeck(kmem[k], name, samples);
        if (deck.empty()) {
          st.SkipWithError(("no deck collapse/" + std::string(name) +
                            " (run from the build's tests directory)")
                               .c_str());
          return;
        }
        DeckOptions opt;
        opt.outDir = deck.parent_path() / "out";
        opt.quiet = true;
        opt.shard = part;
        opt.shards = parts;
        std::ostringstream out;
        const std::clock_t start = std::clock();
        const DeckOutcome o = c2d::runDeck(deck.string(), opt, commands, out);
        seconds[k] += static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
        if (o.exitCode != 0) {
          st.SkipWithError(o.message.c_str());
          return;
        }
        steps[k] += o.total.steps;
        iterations[k] += o.total.iterations;
        cuts[k] += o.total.cuts;
        factorizations[k] += o.total.factorizations;
      }
  }
  for (int k = 0; k < 2; ++k) {
    const std::string suffix = k == 0 ? "_ground" : "_members";
    st.counters["steps" + suffix] = steps[k];
    st.counters["newton_its" + suffix] = iterations[k];
    st.counters["cuts" + suffix] = cuts[k];
    st.counters["factorizations" + suffix] = factorizations[k];
    st.counters["cpu_s" + suffix] = seconds[k];
    st.counters["us_per_it" + suffix] = iterations[k] > 0 ? 1e6 * seconds[k] / iterations[k] : 0.0;
  }
  st.counters["ratio"] = seconds[0] > 0 ? seconds[1] / seconds[0] : 0.0;
}

void BM_SixStoryDemolitionMemberContact(benchmark::State& st) {
  memberContactRatio(st, "six_story_demolition.inp", 0);
}

void BM_SixStoryDemolitionMemberContactEnsemble(benchmark::State& st) {
  memberContactRatio(st, "six_story_demolition_ensemble.inp", 6);
}

// The mesh study deck with its sweep cut down to the 288-element mesh and its
// include files named by absolute path (the copy lives in a scratch directory).
void BM_SixStoryStatic(benchmark::State& st) {
  const std::filesystem::path source = paperDeck("six_story_static_meshes.inp");
  std::ifstream in(source);
  std::stringstream text;
  text << in.rdbuf();
  std::string deck = text.str();
  auto replace = [&](const std::string& from, const std::string& to) {
    const auto at = deck.find(from);
    if (at != std::string::npos) deck.replace(at, from.size(), to);
  };
  const std::string dir = source.parent_path().string() + "/";
  replace("  nc = 2 4 8\n  nb = 4 6 12", "  nc = 8\n  nb = 12");
  replace("INCLude,six_story_frame.inc", "INCLude," + dir + "six_story_frame.inc");
  replace("MESH,six_story_loads.inc", "MESH," + dir + "six_story_loads.inc");
  const std::filesystem::path copy =
      std::filesystem::temp_directory_path() / "c2d_six_story_static_288.inp";
  std::ofstream(copy) << deck;
  runDeck(st, copy);
}

}  // namespace

BENCHMARK(BM_SixStoryWorkflow)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_SixStoryStatic)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_SixStoryDemolition)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_SixStoryDemolitionMemberContact)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_SixStoryDemolitionMemberContactEnsemble)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
