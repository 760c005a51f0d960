#pragma once
// Support for the tests that run whole decks in the test process: a deck
// written to a temporary directory and run with its outputs in <dir>/out, and a
// small Timoshenko cantilever whose tip deflection is known in closed form.
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "macro/DeckRunner.h"
#include "tests/unit/DeckTestSupport.h"

namespace c2d::testing {

struct DeckResult {
  DeckOutcome outcome;
  std::string console;
  std::filesystem::path out;  // the output directory
  std::string log;            // the <stem>.out log
};

// The path of a deck of the source tree's decks/ folder ("rc/catenary.inp").
inline std::string sourceDeck(const std::string& name) {
  return std::string(C2D_SOURCE_DIR) + "/decks/" + name;
}

// Runs the deck at path (its includes beside it) with its outputs in <dir>/out.
inline DeckResult runDeckFile(const DeckTempDir& dir, const std::string& path, bool quiet = true) {
  DeckOptions o;
  o.outDir = dir.path() / "out";
  o.quiet = quiet;
  const SolutionCommands commands;
  std::ostringstream console;
  DeckResult r;
  r.outcome = runDeck(path, o, commands, console);
  r.console = console.str();
  r.out = o.outDir;
  r.log = readText(o.outDir / (std::filesystem::path(path).stem().string() + ".out"));
  return r;
}

// Runs decks/<name> of the source tree ("rc/catenary.inp").
inline DeckResult runSourceDeck(const DeckTempDir& dir, const std::string& name,
                                bool quiet = true) {
  return runDeckFile(dir, sourceDeck(name), quiet);
}

inline DeckResult runDeckText(const DeckTempDir& dir, const std::string& name,
                              const std::string& text, bool quiet = true) {
  return runDeckFile(dir, dir.write(name, text), quiet);
}

// The run ended well (exit code 0); else its message, console and log are shown.
inline void expectRan(const DeckResult& r) {
  ASSERT_EQ(r.outcome.exitCode, 0) << r.outcome.message << r.console << r.log;
}

// A CSV file of numbers with a header row (TPLOt, debris and plan tables).
struct Csv {
  std::vector<std::string> names;
  std::vector<std::vector<double>> rows;
  // The values of column `name` (empty when there is no such column).
  std::vector<double> column(const std::string& name) const {
    std::vector<double> out;
    for (std::size_t c = 0; c < names.size(); ++c)
      if (names[c] == name)
        for (const auto& r : rows) out.push_back(c < r.size() ? r[c] : 0.0);
    return out;
  }
};

inline Csv readCsv(const std::filesystem::path& p) {
  Csv csv;
  std::ifstream in(p);
  std::string line;
  if (std::getline(in, line))
    for (std::stringstream ss(line); std::getline(ss, line, ',');) csv.names.push_back(line);
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) row.push_back(std::stod(cell));
    csv.rows.push_back(std::move(row));
  }
  return csv;
}

// A cantilever of n one-point Timoshenko elements along x (length L), clamped at
// node 1, tip load -P in y at node n+1 scaled by the proportional load.
// Discrete-exact tip deflection (EI = 48000, GA = 500000):
//   v = -P (L^3/(3 EI) (1 - 1/(4 n^2)) + L/GA) times the load factor.
inline double cantileverTip(double P, double L, int n) {
  return -P * (L * L * L / (3 * 48000.0) * (1 - 1 / (4.0 * n * n)) + L / 500000.0);
}

inline std::string cantileverProblem(const std::string& batch, const std::string& data,
                                     const std::string& title = "cantilever") {
  return "FEAP * * " + title +
         "\n  0 0 0 2 3 2\n\n"
         "BLOCk\n  CARTesian n 0 1 1 1\n  1 0 0\n  2 L 0\n\n"
         "MATErial,1\n  FRAMe\n    RESUltant STIFfness 3.6e6 500000 48000\n\n"
         "BOUNdary\n  1 0 1 1 1\n\n"
         "FORCe\n  n+1 0 0 -P 0\n\n"
         "END\nBATCh\n" +
         batch + "END\n" + data + "\n";
}

// A loading in `steps` steps of the ramp, with a TPLOt of the tip deflection
// and the support reaction; `before` and `after` go around the loop.
inline std::string rampBatch(int steps, const std::string& before, const std::string& after) {
  return "  PROP,,1\n  DT,,1/" + std::to_string(steps) + "\n  TPLOt\n" + before + "  LOOP,," +
         std::to_string(steps) + "\n    TIME\n    LOOP,,5\n      TANG,,1\n    NEXT\n  NEXT\n" + after;
}
inline std::string rampData(const std::string& more = {}) {
  return "\n" "disp,n+1,2\nreac,1,2\n\n" + more;
}

// The cantilever problem loaded by rampBatch(steps, before, after), rampData().
inline std::string rampProblem(int steps, const std::string& before, const std::string& after) {
  return cantileverProblem(rampBatch(steps, before, after), rampData());
}

}  // namespace c2d::testing
