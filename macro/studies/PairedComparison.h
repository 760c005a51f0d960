#pragma once
// [ext] Is one plan's lead over another real, or the scatter of a chaotic
// collapse? The plans of an ensemble see the same draws in sample k (common
// random numbers), so they are compared pair by pair:
//   - a share (debris outside the site): McNemar's exact test on the
//     discordant pairs (b: only the first plan's run outside, c: only the
//     second's): p = P(X <= min(b, c)) doubled, X ~ Binomial(b + c, 1/2);
//   - a figure (a reach): Student's paired t test on the differences d_k,
//     t = mean / (sd / sqrt(m)), two-sided p from the t distribution with m - 1
//     degrees of freedom.
// Each gives the samples per plan that would make a lead of the size seen
// significant at 5 % with 80 % power: (z_0.975 + z_0.8)^2 (sd/mean)^2 for the
// paired t (normal approximation); for McNemar, Connor's (1987)
// (z_0.975 sqrt(q) + z_0.8 sqrt(q - delta^2))^2 / delta^2 with q = (b + c)/m
// the discordant share and delta = |b - c|/m.
#include <span>

namespace c2d {

struct PairedTest {
  int pairs = 0;
  double effect = 0;         // mean difference (t test), (c - b)/m (McNemar)
  double statistic = 0;      // t, or b (McNemar)
  double p = 1;              // two-sided
  double samplesNeeded = 0;  // per plan, for 80 % power at 5 % (inf: no lead at all)
  bool significant() const { return p < 0.05; }
};

PairedTest pairedTTest(std::span<const double> differences);
// b: pairs with only the first plan's run outside; c: only the second's; m: pairs.
PairedTest mcNemarTest(int b, int c, int m);

// Student's t distribution function with nu degrees of freedom, and the
// regularized incomplete beta function I_x(a, b) it rests on (continued
// fraction, modified Lentz).
double studentTCdf(double t, double nu);
double incompleteBeta(double a, double b, double x);

}  // namespace c2d
