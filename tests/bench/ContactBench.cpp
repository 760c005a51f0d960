// A frame falling onto a fixed foundation beam with member contact: S stories,
// 5 bays (story 3 m, bay 4 m, 0.3 x 0.4 m sections, E = 30 GPa, FINIte, 4
// elements per member), its column bases 0.05 m above contact distance, gravity,
// decaying mid-point scheme, dt = 0.01 s, 30 steps: free fall for ten steps,
// then the 6 column bases and their neighbours press into the foundation.
// Time per step against the number of elements for S = 5, 10, 20: the cost
// exponent log(t20/t5)/log(n20/n5) (target at most 1.15).
// Run: build/tests/benchmarks --benchmark_filter=FallingFrame
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "macro/DeckRunner.h"

namespace {

constexpr int kBays = 5, kPerMember = 4, kSteps = 30;

int frameElements(int stories) {
  return kPerMember * (stories * (kBays + 1) + stories * kBays) + 4 * kBays + 2;
}

std::string fallingFrameDeck(int stories) {
  std::ostringstream d, elems;
  const int cols = kBays + 1;
  const double r = 0.2;              // sqrt(3 I / A) of the 0.12 m^2, 1.6e-3 m^4 section
  const double base = 2 * r + 0.05;  // column bases above the foundation's centre line
  auto grid = [&](int i, int j) { return i * cols + j + 1; };
  d << "FEAP * * falling frame " << stories << " x " << kBays << "\n  0 0 0 2 3 2\n\nCOORdinates\n";
  for (int i = 0; i <= stories; ++i)
    for (int j = 0; j < cols; ++j)
      d << "  " << grid(i, j) << " 0 " << 4.0 * j << " " << base + 3.0 * i << "\n";
  int next = grid(stories, kBays) + 1;
  int e = 1;
  auto member = [&](int a, int b, double xa, double ya, double xb, double yb, int mat, int n) {
    int prev = a;
    for (int k = 1; k <= n; ++k) {
      int node = b;
      if (k < n) {
        node = next++;
        const double s = static_cast<double>(k) / n;
        d << "  " << node << " 0 " << xa + s * (xb - xa) << " " << ya + s * (yb - ya) << "\n";
      }
      elems << "  " << e++ << " 0 " << mat << " " << prev << " " << node << "\n";
      prev = node;
    }
  };
  for (int i = 0; i < stories; ++i)
    for (int j = 0; j < cols; ++j)
      member(grid(i, j), grid(i + 1, j), 4.0 * j, base + 3.0 * i, 4.0 * j, base + 3.0 * (i + 1), 1,
             kPerMember);
  for (int i = 1; i <= stories; ++i)
    for (int j = 0; j < kBays; ++j)
      member(grid(i, j), grid(i, j + 1), 4.0 * j, base + 3.0 * i, 4.0 * (j + 1), base + 3.0 * i, 1,
             kPerMember);
  // The foundation: a fixed beam from x = -1 to 4 B + 1, 1 m elements.
  const int f0 = next++, f1 = next++;
  d << "  " << f0 << " 0 -1 0\n  " << f1 << " 0 " << 4.0 * kBays + 1 << " 0\n";
  const int inner = next;
  member(f0, f1, -1, 0, 4.0 * kBays + 1, 0, 2, 4 * kBays + 2);
  d << "\nELEMents\n" << elems.str();
  for (int m = 1; m <= 2; ++m)
    d << "\nMATErial," << m << "\n  FRAMe\n    ELAStic ISOTropic 30e6 0.2\n"
      << "    CROSs section 0.12 1.6e-3\n    DENSity,,2.5\n    FINIte\n";
  d << "\nBOUNdary\n  " << f0 << " 0 1 1 1\n  " << f1 << " 0 1 1 1\n";
  for (int n = inner; n < next; ++n) d << "  " << n << " 0 1 1 1\n";
  d << "\nCONTact\n  MEMBers,,1e6\n\nGRAVity,,0,-9.81\n\nEND\nBATCh\n  DYNAmic,ENERgy,0.1,0.1\n"
    << "  DT,,0.01\n  LOOP,," << kSteps << "\n    TIME\n    LOOP,,20\n      TANG,,1\n    NEXT\n"
    << "  NEXT\nEND\nSTOP\n";
  return d.str();
}

void BM_FallingFrame(benchmark::State& st) {
  const int stories = static_cast<int>(st.range(0));
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "c2d_bench_falling";
  std::filesystem::create_directories(dir);
  const std::filesystem::path deck = dir / ("falling_" + std::to_string(stories) + ".inp");
  std::ofstream(deck) << fallingFrameDeck(stories);
  c2d::SolutionCommands commands;
  c2d::DeckOptions opt;
  opt.outDir = dir;
  opt.quiet = true;
  int iterations = 0, steps = 0;
  for (auto _ : st) {
    std::ostringstream out;
    const c2d::DeckOutcome o = c2d::runDeck(deck.string(), opt, commands, out);
    if (o.exitCode != 0) {
      st.SkipWithError(o.message.c_str());
      return;
    }
    iterations = o.total.iterations;
    steps = o.total.steps;
  }
  st.counters["elements"] = frameElements(stories);
  st.counters["steps"] = steps;
  st.counters["newton_its"] = iterations;
  st.counters["s_per_step"] = benchmark::Counter(
      steps, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

}  // namespace

BENCHMARK(BM_FallingFrame)->Arg(5)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond)->Iterations(3);
