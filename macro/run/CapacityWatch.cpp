#include "macro/run/CapacityWatch.h"

#include <algorithm>
#include <cstdio>

#include "core/Hinge.h"

namespace c2d {

void CapacityWatch::observe(int element, double ratio, double t, std::ostream& log) {
  maxRatio_ = std::max(maxRatio_, ratio);
  if (element < 0 || ratio <= 1 + kCapacityTolerance) return;
  if (static_cast<int>(warned_.size()) <= element) warned_.resize(element + 1, 0);
  if (warned_[element]) return;
  warned_[element] = 1;
  ++warnedCount_;
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "  warning: element %d carries |M|/Mu = %.4f at t = %.6e, past its capacity by "
                "more than %.1f %%: the step's solution jumped across the hinge's opening (another "
                "branch of a contact or a law between two sub-steps)\n",
                element + 1, ratio, t, 100 * kCapacityTolerance);
  log << buf;
}

}  // namespace c2d
