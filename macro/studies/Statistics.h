#pragma once
// [ext] The statistics of an ensemble's runs (plans decided on distributions):
// quantiles of a figure, the Wilson interval of a share, the rank correlation
// of a drawn value with a figure.
#include <span>
#include <utility>
#include <vector>

namespace c2d {

// The p-quantile (0 <= p <= 1) of the values (any order, at least one): the
// linear interpolation between order statistics of Hyndman and Fan's type 7
// (R's and NumPy's default): h = (n - 1) p, x(floor h) + frac(h) (x(floor h + 1)
// - x(floor h)), x sorted ascending from 0.
double quantile(std::span<const double> values, double p);

// The 95 % Wilson score interval of a share k/n (z = 1.96; n = 0: [0, 1]):
//   (p + z^2/2n -+ z sqrt(p (1 - p)/n + z^2/4n^2)) / (1 + z^2/n), p = k/n.
// Unlike p -+ z sqrt(p(1-p)/n) it stays inside [0, 1] and is not empty at k = 0.
constexpr double kWilsonZ = 1.96;
std::pair<double, double> wilsonInterval(int k, int n, double z = kWilsonZ);

// Spearman's rank correlation: Pearson's correlation of the ranks, ties given
// their mean rank. NaN when fewer than 3 pairs or either side is constant.
double rankCorrelation(std::span<const double> x, std::span<const double> y);
// Ranks from 1 (ties: their mean rank), in the values' order.
std::vector<double> ranks(std::span<const double> values);

}  // namespace c2d
