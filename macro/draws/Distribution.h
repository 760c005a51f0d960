#pragma once
// [ext] The laws a parameter of an ensemble is drawn from (ENSEmble records
// `name = NORMal mean sd | LOGNormal median cov | UNIForm lo hi`). A draw is
// the law's quantile of one uniform number u (inverse transform), so that a
// larger u always gives a larger value: common random numbers keep their
// order from plan to plan.
//   NORMal mean sd       mean + sd z, z = Phi^-1(u)
//   LOGNormal median cov median exp(s z), s = sqrt(ln(1 + cov^2)): the median
//                        and the coefficient of variation (sd / mean) of the value
//   UNIForm lo hi        lo + (hi - lo) u
#include <string>

namespace c2d {

enum class Law { Normal, LogNormal, Uniform };

struct Distribution {
  Law law = Law::Uniform;
  double a = 0, b = 1;  // (mean, sd), (median, cov) or (lo, hi)

  double quantile(double u) const;  // u in (0, 1)
  double cdf(double x) const;
  // "NORMal 1 0.1", for the log.
  std::string text() const;
};

// The standard normal distribution function and its inverse (p in (0, 1); the
// inverse is exact to a few units of the last place: a starting value from
// Abramowitz and Stegun 26.2.23 refined by Halley's method on erfc).
double normalCdf(double x);
double normalQuantile(double p);

}  // namespace c2d
