#pragma once
// Overlays of the same PLOT,CURVe across the runs of a parameter study (a
// SWEEp or a top-level LOOP): one chart per curve with one legend entry per
// run, written at the end of the deck as <stem>_<y>_vs_<x>.svg (the deck's
// stem; each run's own chart carries the run's stem).
#include <filesystem>
#include <string>
#include <vector>

#include "macro/RunOutputs.h"

namespace c2d {

class CurveOverlay {
 public:
  // The curves of one run, with its legend entry ("ks = -393") and the title of
  // its problem.
  void add(const std::string& runLabel, const std::string& title, const std::vector<CurveData>& curves);
  // Writes every curve that at least two runs drew; returns the files written.
  std::vector<std::filesystem::path> write(const std::filesystem::path& outDir, const std::string& stem) const;
  int numCurves() const { return static_cast<int>(groups_.size()); }

 private:
  struct Group {
    CurveSpec spec;
    std::string title;
    std::vector<std::pair<std::string, std::vector<std::pair<double, double>>>> series;
  };
  std::vector<Group> groups_;
};

}  // namespace c2d
