#pragma once
// Shared by the ensemble tests: the Kolmogorov-Smirnov statistic of values
// against a distribution function, its 1 % critical value, and a run of a
// table that ended well inside the site with the given figures.
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "macro/studies/EnsembleTable.h"

namespace c2d::testing {

// The Kolmogorov-Smirnov statistic of the values against a distribution function.
inline double ksStatistic(std::vector<double> x, const std::function<double(double)>& cdf) {
  std::sort(x.begin(), x.end());
  const double n = static_cast<double>(x.size());
  double d = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double f = cdf(x[i]);
    d = std::max({d, f - i / n, (i + 1) / n - f});
  }
  return d;
}

// The 1 % critical value of the KS statistic: 1.628 / sqrt(n) (a correct
// sampler exceeds it for one seed in a hundred; the seeds here are fixed).
inline double ksCritical(int n) { return 1.628 / std::sqrt(static_cast<double>(n)); }

// A run that ended well, its debris inside the site, with the given figures.
inline EnsembleRun okRun(std::map<std::string, double> figures) {
  EnsembleRun r;
  r.ok = r.debris = true;
  r.site = "inside";
  r.figures = std::move(figures);
  return r;
}

}  // namespace c2d::testing
