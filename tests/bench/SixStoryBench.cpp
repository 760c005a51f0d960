// The paper's six-story frame, 288 elements:
//  - SixStoryWorkflow: decks/paper/six_story_collapse.inp: the failure phase
//    until the hinges have formed, HINGE2JOINT, the collapse phase with ground
//    contact and gravity until the frame lies on the ground;
//  - SixStoryStatic: the static failure analysis to the full mechanism
//    (decks/paper/six_story_static_meshes.inp, its 288-element run only).
// Counters: steps, Newton iterations, factorizations, seconds per iteration.
// Run: build/tests/benchmarks --benchmark_filter=SixStory
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "macro/DeckRunner.h"

namespace {

// The deck sits in the source tree: found from this file's own path.
std::filesystem::path paperDeck(const char* name) {
  return std::filesystem::path(__FILE__).parent_path().parent_path().parent_path() / "decks" /
         "paper" / name;
}

void runDeck(benchmark::State& st, const std::filesystem::path& deck) {
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
  int iterations = 0, factorizations = 0, steps = 0, cuts = 0;
  for (auto _ : st) {
    std::ostringstream out;
    const c2d::DeckOutcome o = c2d::runDeck(deck.string(), opt, commands, out);
    if (o.exitCode != 0) {
      st.SkipWithError(o.message.c_str());
      return;
    }
    iterations = o.total.iterations;
    factorizations = o.total.factorizations;
    steps = o.total.steps;
    cuts = o.total.cuts;
  }
  st.counters["steps"] = steps;
  st.counters["newton_its"] = iterations;
  st.counters["factorizations"] = factorizations;
  st.counters["cuts"] = cuts;
  st.counters["s_per_it"] = benchmark::Counter(
      iterations, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_SixStoryWorkflow(benchmark::State& st) { runDeck(st, paperDeck("six_story_collapse.inp")); }

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
