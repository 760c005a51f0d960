// Frame push benchmark (deck generator in FrameDeck.h): the whole run of the
// S x B frame with N elements per member, and the time per Newton iteration
// against the number of equations. Run: build/tests/benchmarks --benchmark_filter=Frame
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>

#include "tests/bench/DeckBench.h"
#include "tests/bench/FrameDeck.h"

namespace {

void BM_FramePush(benchmark::State& st) {
  const int S = static_cast<int>(st.range(0)), B = static_cast<int>(st.range(1)),
            N = static_cast<int>(st.range(2));
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "c2d_bench";
  std::filesystem::create_directories(dir);
  const std::filesystem::path deck =
      dir / ("frame_" + std::to_string(S) + "x" + std::to_string(B) + ".inp");
  std::ofstream(deck) << c2d::bench::frameDeck(S, B, N);
  c2d::bench::runDeck(st, deck);
  const int nodes = (S + 1) * (B + 1) + (S * (B + 1) + S * B) * (N - 1);
  st.counters["dofs"] = 3.0 * (nodes - (B + 1));
}

}  // namespace

BENCHMARK(BM_FramePush)
    ->Args({5, 3, 8})
    ->Args({10, 5, 8})
    ->Args({20, 10, 8})
    ->Args({40, 20, 8})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
