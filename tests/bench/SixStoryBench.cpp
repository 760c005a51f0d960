// The paper's six-story frame, 288 elements:
//  - SixStoryWorkflow: decks/paper/six_story_collapse.inp: the failure phase
//    until the hinges have formed, HINGE2JOINT, the collapse phase with ground
//    contact and gravity until the frame lies on the ground;
//  - SixStoryStatic: the static failure analysis to the full mechanism
//    (decks/paper/six_story_static_meshes.inp, its 288-element run only);
//  - SixStoryDemolition: the main example, decks/collapse/six_story_demolition.inp
//    (pushed to its mechanism, HINGe2joint,INELastic, released, falls onto a
//    crushing ground with friction; target 2 s on the 2-core test machine).
// Counters: steps, Newton iterations, factorizations, seconds per iteration.
// Run: build/tests/benchmarks --benchmark_filter=SixStory
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/bench/DeckBench.h"

namespace {

using c2d::bench::runDeck;

std::filesystem::path paperDeck(const char* name) { return c2d::bench::sourceDeck("paper", name); }

void BM_SixStoryWorkflow(benchmark::State& st) { runDeck(st, paperDeck("six_story_collapse.inp")); }

void BM_SixStoryDemolition(benchmark::State& st) {
  runDeck(st, c2d::bench::sourceDeck("collapse", "six_story_demolition.inp"));
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
