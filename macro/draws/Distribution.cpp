#include "macro/draws/Distribution.h"

#include <cmath>
#include <cstdio>
#include <numbers>

namespace c2d {

double normalCdf(double x) { return 0.5 * std::erfc(-x / std::numbers::sqrt2); }

namespace {

// The lower half, p <= 0.5.
double lowerQuantile(double p) {
  // Abramowitz and Stegun 26.2.23 (error below 4.5e-4).
  const double t = std::sqrt(-2 * std::log(p));
  double x = -(t - (2.515517 + t * (0.802853 + t * 0.010328)) /
                       (1 + t * (1.432788 + t * (0.189269 + t * 0.001308))));
  // Halley's method on Phi(x) - p: cubic convergence from there.
  for (int i = 0; i < 3; ++i) {
    const double e = normalCdf(x) - p;
    const double u = e * std::sqrt(2 * std::numbers::pi) * std::exp(0.5 * x * x);
    x -= u / (1 + 0.5 * x * u);
  }
  return x;
}

}  // namespace

double normalQuantile(double p) {
  if (!(p > 0 && p < 1)) return p == 0 ? -INFINITY : p == 1 ? INFINITY : NAN;
  // 1 - p is exact for p >= 0.5 (both in [0.5, 1]).
  return p <= 0.5 ? lowerQuantile(p) : -lowerQuantile(1 - p);
}

double Distribution::quantile(double u) const {
  switch (law) {
    case Law::Normal:
      return a + b * normalQuantile(u);
    case Law::LogNormal:
      return a * std::exp(std::sqrt(std::log1p(b * b)) * normalQuantile(u));
    case Law::Uniform:
      break;
  }
  return a + (b - a) * u;
}

double Distribution::cdf(double x) const {
  switch (law) {
    case Law::Normal:
      return b > 0 ? normalCdf((x - a) / b) : (x >= a ? 1.0 : 0.0);
    case Law::LogNormal: {
      const double s = std::sqrt(std::log1p(b * b));
      if (x <= 0) return 0;
      return s > 0 ? normalCdf(std::log(x / a) / s) : (x >= a ? 1.0 : 0.0);
    }
    case Law::Uniform:
      break;
  }
  if (b <= a) return x >= a ? 1.0 : 0.0;
  return x <= a ? 0.0 : x >= b ? 1.0 : (x - a) / (b - a);
}

std::string Distribution::text() const {
  char buf[96];
  const char* name = law == Law::Normal      ? "NORMal"
                     : law == Law::LogNormal ? "LOGNormal"
                                             : "UNIForm";
  std::snprintf(buf, sizeof buf, "%s %g %g", name, a, b);
  return buf;
}

}  // namespace c2d
