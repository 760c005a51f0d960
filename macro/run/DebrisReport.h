#pragma once
// The debris report of a run with ground contact: where the debris ends up
// against the footprint and the site (macro/output/Debris.h), as the log's
// lines, <stem>_debris.csv (one row) and, when PLOT,DEBRis asked for one, the
// picture <stem>_debris.svg, drawn again with the final state at the end.
#include <filesystem>
#include <ostream>
#include <string>

#include "core/Model.h"
#include "core/State.h"
#include "macro/output/Debris.h"
#include "macro/run/RunOptions.h"

namespace c2d {

class DebrisReport {
 public:
  DebrisReport(const RunOptions& options, std::string problemTitle);

  // The run's end with the debris figures d: the log's lines and the csv row.
  // True when PLOT,DEBRis asked for the picture (to be drawn again now).
  bool write(std::ostream& log, const DebrisFigures& d) const;
  // PLOT,DEBRis: the picture of the state s, whose figures are d.
  void plot(std::ostream& log, const Model& model, const State& s, const DebrisFigures& d);

 private:
  std::filesystem::path outDir_;
  std::string stem_;
  std::string label_;
  std::string problemTitle_;
  bool pictures_ = true;
  bool plotted_ = false;
};

}  // namespace c2d
