#pragma once
// The bytes an ensemble study wrote, per run: the run's own files (<stem>_*,
// <stem>.*), its part of the deck's log (from its "run k of n," line to the
// next) and its share of the ensemble and timing tables; the rest (the plans'
// statistics, pictures, overlays) is the study's. Shared by
// EnsembleOutputsTest and tests/bench/EnsembleBench.cpp.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>

#include "macro/studies/EnsembleTable.h"

namespace c2d::testing {

struct StudyBytes {
  std::map<int, double> run;    // by run number
  double shared = 0;            // the study's files
  double first = 0, other = 0;  // the largest run of a plan's sample 1, of the other samples
  int plans = 0;
  // A study of `plans` plans of `samples` samples each (the shared files scale
  // with the plans).
  double study(int p, int samples) const {
    return p * first + p * (samples - 1) * other + shared * p / std::max(1, plans);
  }
};

inline std::string studyText(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

inline StudyBytes studyBytes(const std::filesystem::path& dir, const std::string& stem) {
  namespace fs = std::filesystem;
  const std::string tables[] = {stem + "_ensemble.csv", stem + "_timing.csv"};
  const EnsembleData d = readEnsembleTable(studyText(dir / tables[0]), 0);
  const std::string n = std::to_string(d.runs.size());
  StudyBytes b;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    const auto size = static_cast<double>(entry.file_size());
    const EnsembleRun* owner = nullptr;
    for (const EnsembleRun& r : d.runs)
      if (name.rfind(r.stem + "_", 0) == 0 || name.rfind(r.stem + ".", 0) == 0) owner = &r;
    if (owner)
      b.run[owner->run] += size;
    else if (name != stem + ".out" && name != tables[0] && name != tables[1])
      b.shared += size;
  }
  const std::string log = studyText(dir / (stem + ".out"));
  for (const EnsembleRun& r : d.runs) {
    const std::size_t from = log.find("  run " + std::to_string(r.run) + " of " + n + ",");
    const std::size_t to = log.find("  run " + std::to_string(r.run + 1) + " of " + n + ",");
    if (from != std::string::npos)
      b.run[r.run] += static_cast<double>((to == std::string::npos ? log.size() : to) - from);
  }
  for (const std::string& t : tables)
    if (fs::exists(dir / t))
      for (const EnsembleRun& r : d.runs)
        b.run[r.run] += static_cast<double>(fs::file_size(dir / t)) / d.runs.size();
  for (const EnsembleRun& r : d.runs) {
    double& largest = r.sample == 1 ? b.first : b.other;
    largest = std::max(largest, b.run[r.run]);
    b.plans = std::max(b.plans, r.plan);
  }
  return b;
}

}  // namespace c2d::testing
