#include "solvers/NewtonVerdict.h"

#include <algorithm>

#include "solvers/Analysis.h"
#include "solvers/ConvergenceTest.h"

namespace c2d {

NewtonVerdict newtonVerdict(const IterationInfo& info, const std::vector<IterationInfo>& history) {
  const std::vector<IterationInfo>& h = history;
  if (h.size() > 4 && info.energy > kNewtonBlowUp * h.front().energy)
    return NewtonVerdict::Diverged;
  // Once the line search took over, only its own iterations count: the plain
  // iterations' two-cycle that called it in says nothing of whether it breaks
  // the cycle.
  std::size_t from = 0;
  for (std::size_t k = h.size(); k-- > 0;)
    if (h[k].globalized) {
      from = k + 1;
      break;
    }
  if (!info.converged && h.size() - from >= 6) {
    double energies[6];  // on the stack: no allocation inside the Newton loop
    const std::size_t n = 6;
    for (std::size_t k = 0; k < n; ++k) energies[k] = h[h.size() - n + k].energy;
    if (repeatsWithPeriod(energies, n, 2, 3)) return NewtonVerdict::Stalled;
  }
  return info.converged ? NewtonVerdict::Converged : NewtonVerdict::Iterating;
}

}  // namespace c2d
