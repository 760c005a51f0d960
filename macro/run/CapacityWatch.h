#pragma once
// Members past their capacity, kept at every commit: the run's largest |M|/Mu
// (the summary's "max |M|/Mu") and a warning, once per element, for a moment
// past Mu by more than kCapacityTolerance (core/Hinge.h), with the element and
// the time. The hinges' event location keeps every member within the band; a
// member past it is a result that is not the model's, and the run says so.
#include <ostream>
#include <vector>

namespace c2d {

class CapacityWatch {
 public:
  // ratio = |M|/Mu of element (0-based; -1: none) at time t.
  void observe(int element, double ratio, double t, std::ostream& log);

  double maxRatio() const { return maxRatio_; }
  // The largest ratio of the run before a restart.
  void setMaxRatio(double r) { maxRatio_ = r; }
  int warned() const { return warnedCount_; }

 private:
  double maxRatio_ = 0;
  std::vector<char> warned_;  // per element
  int warnedCount_ = 0;
};

}  // namespace c2d
