#include "macro/studies/PairedComparison.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace c2d {

namespace {

constexpr double kZ975 = 1.959963984540054, kZ80 = 0.8416212335729143;

// The continued fraction of I_x(a, b) (converges for x < (a + 1)/(a + b + 2)).
double betaFraction(double a, double b, double x) {
  constexpr double tiny = 1e-300;
  double c = 1, d = 1 - (a + b) * x / (a + 1);
  if (std::abs(d) < tiny) d = tiny;
  d = 1 / d;
  double h = d;
  for (int m = 1; m <= 300; ++m) {
    const double mm = m;
    const double even = mm * (b - mm) * x / ((a + 2 * mm - 1) * (a + 2 * mm));
    d = 1 + even * d;
    if (std::abs(d) < tiny) d = tiny;
    c = 1 + even / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1 / d;
    h *= d * c;
    const double odd = -(a + mm) * (a + b + mm) * x / ((a + 2 * mm) * (a + 2 * mm + 1));
    d = 1 + odd * d;
    if (std::abs(d) < tiny) d = tiny;
    c = 1 + odd / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1 / d;
    const double step = d * c;
    h *= step;
    if (std::abs(step - 1) < 1e-15) break;
  }
  return h;
}

}  // namespace

double incompleteBeta(double a, double b, double x) {
  if (x <= 0) return 0;
  if (x >= 1) return 1;
  const double front = std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) +
                                a * std::log(x) + b * std::log1p(-x));
  if (x < (a + 1) / (a + b + 2)) return front * betaFraction(a, b, x) / a;
  return 1 - front * betaFraction(b, a, 1 - x) / b;
}

double studentTCdf(double t, double nu) {
  const double tail = 0.5 * incompleteBeta(0.5 * nu, 0.5, nu / (nu + t * t));
  return t >= 0 ? 1 - tail : tail;
}

PairedTest pairedTTest(std::span<const double> d) {
  PairedTest r;
  r.pairs = static_cast<int>(d.size());
  if (d.empty()) return r;
  double mean = 0;
  for (double x : d) mean += x;
  mean /= static_cast<double>(d.size());
  double ss = 0;
  for (double x : d) ss += (x - mean) * (x - mean);
  r.effect = mean;
  const double m = static_cast<double>(d.size());
  const double sd = d.size() > 1 ? std::sqrt(ss / (m - 1)) : 0.0;
  if (d.size() < 2) {  // one pair: no scatter to judge it by, no test
    r.statistic = std::numeric_limits<double>::quiet_NaN();
    r.p = 1.0;
    r.samplesNeeded = std::numeric_limits<double>::infinity();
    return r;
  }
  if (sd == 0) {
    // Every pair differs by the same amount: certain when it is not zero and
    // seen in three pairs at least (two equal differences may be chance).
    r.statistic = mean == 0 ? 0 : std::copysign(std::numeric_limits<double>::infinity(), mean);
    r.p = mean == 0 || d.size() < 3 ? 1.0 : 0.0;
    r.samplesNeeded = mean == 0 ? std::numeric_limits<double>::infinity() : 2;
    return r;
  }
  r.statistic = mean / (sd / std::sqrt(m));
  r.p = d.size() > 1 ? 2 * (1 - studentTCdf(std::abs(r.statistic), m - 1)) : 1.0;
  r.samplesNeeded =
      mean == 0 ? std::numeric_limits<double>::infinity() : std::pow((kZ975 + kZ80) * sd / mean, 2);
  return r;
}

PairedTest mcNemarTest(int b, int c, int m) {
  PairedTest r;
  r.pairs = m;
  r.statistic = b;
  const int n = b + c, k = std::min(b, c);
  r.effect = m > 0 ? static_cast<double>(c - b) / m : 0.0;
  // P(X <= k), X ~ Binomial(n, 1/2), by the terms' logarithms.
  double tail = 0;
  for (int i = 0; i <= k; ++i)
    tail += std::exp(std::lgamma(n + 1.0) - std::lgamma(i + 1.0) - std::lgamma(n - i + 1.0) -
                     n * std::log(2.0));
  r.p = n == 0 ? 1.0 : std::min(1.0, 2 * tail);
  if (m <= 0 || b == c) {
    r.samplesNeeded = std::numeric_limits<double>::infinity();
    return r;
  }
  const double q = static_cast<double>(n) / m, delta = std::abs(static_cast<double>(c - b)) / m;
  r.samplesNeeded =
      std::pow(kZ975 * std::sqrt(q) + kZ80 * std::sqrt(std::max(0.0, q - delta * delta)), 2) /
      (delta * delta);
  return r;
}

}  // namespace c2d
