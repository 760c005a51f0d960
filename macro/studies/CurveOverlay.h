#pragma once
// Overlays of the same PLOT,CURVe across the runs of a parameter study (a
// SWEEp, an ENSEmble's plans, or a top-level LOOP): one chart per curve with
// one legend entry per run, written at the end of the deck as
// <stem>_<y>_vs_<x>.svg (the deck's stem; each run's own chart carries the
// run's stem).
//
// A shard of a study writes its runs' curves as <stem>_part<i>of<n>_curves.csv
// (csv(): one row per point, the numbers exact) so that `collapse2d merge`
// draws the overlays of the whole study, the same as one run would.
#include <filesystem>
#include <string>
#include <vector>

#include "macro/run/RunOutputs.h"

namespace c2d {

class CurveOverlay {
 public:
  // The curves of run `run` (its number in the deck), with its legend entry
  // ("ks = -393") and the title of its problem. Runs are drawn in the order added.
  void add(int run, const std::string& runLabel, const std::string& title,
           const std::vector<CurveData>& curves);
  // Writes every curve that at least two runs drew; returns the files written.
  std::vector<std::filesystem::path> write(const std::filesystem::path& outDir,
                                           const std::string& stem) const;
  int numRuns() const { return static_cast<int>(runs_.size()); }

  // The runs' curves as CSV: run,label,title,written,x_column,y_column,x_label,
  // y_label,x_scale,y_scale,x,y.
  std::string csv() const;
  // The runs of csv() texts joined in run order; throws std::runtime_error
  // (line, why) for a malformed text.
  void addCsv(const std::string& text);
  void sortByRun();

 private:
  struct Run {
    int run = 0;
    std::string label, title;
    std::vector<CurveData> curves;
  };
  std::vector<Run> runs_;
};

}  // namespace c2d
