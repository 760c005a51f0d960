#include "macro/studies/BinomialBound.h"

#include <cmath>

namespace c2d {

namespace {

// P(X <= k) for X ~ Binomial(n, p), 0 < p < 1, summed in log space.
double binomialCdf(int k, long long n, double p) {
  const double lp = std::log(p), lq = std::log1p(-p);
  double sum = 0;
  for (long long i = 0; i <= k; ++i) {
    const double logTerm = std::lgamma(static_cast<double>(n) + 1) -
                           std::lgamma(static_cast<double>(i) + 1) -
                           std::lgamma(static_cast<double>(n - i) + 1) +
                           static_cast<double>(i) * lp + static_cast<double>(n - i) * lq;
    sum += std::exp(logTerm);
  }
  return sum;
}

double upperBound(int k, long long n, double confidence) {
  if (n <= 0 || k >= n) return 1.0;
  const double alpha = 1.0 - confidence;
  if (k == 0) return -std::expm1(std::log(alpha) / static_cast<double>(n));
  // The CDF falls as p grows: bisect for CDF = alpha.
  double lo = 0, hi = 1;
  for (int it = 0; it < 200 && hi - lo > 1e-15; ++it) {
    const double mid = 0.5 * (lo + hi);
    (binomialCdf(k, n, mid) > alpha ? lo : hi) = mid;
  }
  return hi;
}

}  // namespace

double clopperPearsonUpper(int k, int n, double confidence) {
  return upperBound(k, n, confidence);
}

long long runsToShowBelow(int k, int n, double level, double confidence) {
  constexpr long long kMost = 1000000000;
  long long lo = n, hi = n > 0 ? n : 1;
  if (upperBound(k, lo, confidence) < level) return lo;
  // Grow the bracket, then bisect (the bound falls as runs are added).
  while (upperBound(k, hi, confidence) >= level) {
    lo = hi;
    hi *= 2;
    if (hi > kMost) return -1;
  }
  while (hi - lo > 1) {
    const long long mid = lo + (hi - lo) / 2;
    (upperBound(k, mid, confidence) < level ? hi : lo) = mid;
  }
  return hi;
}

}  // namespace c2d
