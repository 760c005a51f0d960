#pragma once
// A deck of the source tree run as a benchmark (one run per iteration), with
// its counters: steps, Newton iterations, factorizations, cut steps, seconds
// per iteration.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <sstream>
#include <string>

#include "macro/DeckRunner.h"

namespace c2d::bench {

// decks/<topic>/<name>, found from this file's own path.
inline std::filesystem::path sourceDeck(const char* topic, const char* name) {
  return std::filesystem::path(__FILE__).parent_path().parent_path().parent_path() / "decks" /
         topic / name;
}

inline void runDeck(benchmark::State& st, const std::filesystem::path& deck) {
  if (!std::filesystem::exists(deck)) {
    st.SkipWithError(("no deck " + deck.string()).c_str());
    return;
  }
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("c2d_bench_" + deck.stem().string());
  std::filesystem::create_directories(dir);
  SolutionCommands commands;
  DeckOptions opt;
  opt.outDir = dir;
  opt.quiet = true;
  int iterations = 0, factorizations = 0, steps = 0, cuts = 0;
  for (auto _ : st) {
    std::ostringstream out;
    const DeckOutcome o = c2d::runDeck(deck.string(), opt, commands, out);
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

}  // namespace c2d::bench
