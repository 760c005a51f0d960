// The paper's whole six-story workflow (decks/paper/six_story_collapse.inp,
// 288 elements): the failure phase until the hinges have formed, HINGE2JOINT,
// the collapse phase with ground contact and gravity until the frame lies on
// the ground. Counters: steps, Newton iterations, seconds per iteration.
// Run: build/tests/benchmarks --benchmark_filter=SixStory
#include <benchmark/benchmark.h>

#include <filesystem>
#include <sstream>

#include "macro/DeckRunner.h"

namespace {

// The deck sits in the source tree: found from this file's own path.
std::filesystem::path paperDeck(const char* name) {
  return std::filesystem::path(__FILE__).parent_path().parent_path().parent_path() / "decks" / "paper" / name;
}

void BM_SixStoryWorkflow(benchmark::State& st) {
  const std::filesystem::path deck = paperDeck("six_story_collapse.inp");
  if (!std::filesystem::exists(deck)) {
    st.SkipWithError(("no deck " + deck.string()).c_str());
    return;
  }
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "c2d_bench_six_story";
  std::filesystem::create_directories(dir);
  c2d::SolutionCommands commands;
  c2d::DeckOptions opt;
  opt.outDir = dir;
  opt.quiet = true;
  int iterations = 0, steps = 0, cuts = 0;
  for (auto _ : st) {
    std::ostringstream out;
    const c2d::DeckOutcome o = c2d::runDeck(deck.string(), opt, commands, out);
    if (o.exitCode != 0) {
      st.SkipWithError(o.message.c_str());
      return;
    }
    iterations = o.total.iterations;
    steps = o.total.steps;
    cuts = o.total.cuts;
  }
  st.counters["steps"] = steps;
  st.counters["newton_its"] = iterations;
  st.counters["cuts"] = cuts;
  st.counters["s_per_it"] =
      benchmark::Counter(iterations, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

}  // namespace

BENCHMARK(BM_SixStoryWorkflow)->Unit(benchmark::kMillisecond)->Iterations(1);
