// Ensemble throughput: the felling plans' ensemble (decks/demolition/
// felling_ensemble_short.inp: 3 plans x 2 samples of the ten-storey felling,
// each run on to rest) with `collapse2d run -j 2`: its runs split over two
// processes and merged. Counter: runs per minute of wall time. The full
// ensemble (felling_ensemble.inp, 3 x 20) is timed from the command line
// (docs/history.md, "Ensembles").
// Counters of the outputs (tests/unit/StudyBytes.h): the bytes of a plan's
// first sample (all its outputs: ParaView frames, pictures, the full log),
// of another sample (its time history, debris row, log section, table rows)
// and of a study of 3 plans x 200 samples. Measured (2026-12, one process):
// first about 18.9 MB (16.9 MB of them 272 ParaView frames, 1.9 MB log),
// other 52 kB (mostly the time history), so 600 runs: 3 x 18.9 + 597 x
// 0.052 = 88 MB.
// Run: build/tests/benchmarks --benchmark_filter=Ensemble
#include <benchmark/benchmark.h>

#include <chrono>
#include <filesystem>
#include <sstream>

#include "macro/batch/ParallelRuns.h"
#include "macro/DeckRunner.h"
#include "tests/bench/DeckBench.h"
#include "tests/unit/StudyBytes.h"

namespace {

void BM_FellingEnsembleTwoProcesses(benchmark::State& st) {
  const std::filesystem::path deck =
      c2d::bench::sourceDeck("demolition", "felling_ensemble_short.inp");
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "c2d_bench_ensemble";
  std::filesystem::remove_all(dir);
  c2d::BatchOptions options;
  options.deck.outDir = dir;
  options.deck.quiet = true;
  options.jobs = 2;
  const c2d::SolutionCommands commands;
  double seconds = 0;
  int runs = 0;
  for (auto _ : st) {
    std::ostringstream out, err;
    const auto start = std::chrono::steady_clock::now();
    const int status = c2d::runDeckInParallel(deck.string(), options, c2d::deckCalls(commands), out, err);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (status != 0) {
      st.SkipWithError(("the ensemble failed: " + err.str()).c_str());
      return;
    }
    runs += 6;
  }
  const c2d::testing::StudyBytes bytes = c2d::testing::studyBytes(dir, "felling_ensemble_short");
  st.counters["first_sample_MB"] = bytes.first * 1e-6;
  st.counters["other_sample_kB"] = bytes.other * 1e-3;
  st.counters["MB_of_600_runs"] = bytes.study(3, 200) * 1e-6;
  st.counters["runs"] = runs;
  st.counters["runs_per_minute"] = seconds > 0 ? 60 * runs / seconds : 0;
}

}  // namespace

BENCHMARK(BM_FellingEnsembleTwoProcesses)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
