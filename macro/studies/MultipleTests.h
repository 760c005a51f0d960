#pragma once
// [ext] Many tests at once: a table of rank correlations holds dozens of them,
// and at 5 % one in twenty unrelated inputs stands out by chance. Each
// correlation gets its p-value, and the family of a plan's tests is corrected
// by Holm's step-down rule (Holm 1979), which holds the probability of any
// false mark at 5 % whatever the dependence between the tests (unlike
// Benjamini-Hochberg, which bounds the expected share of false marks).
#include <span>
#include <vector>

namespace c2d {

// The two-sided p-value of Spearman's rho over n pairs under independence.
// Below kExactRankPairs pairs the exact permutation law: the share of the n!
// orderings whose |rho| reaches the observed one (n = 3 and rho = 1: 1/3; the
// t law would say 0). From there Student's t with n - 2 degrees of freedom,
// t = rho sqrt((n - 2) / (1 - rho^2)), as scipy's spearmanr (within a few
// hundredths of the exact law at n = 10). NaN when rho is NaN or n < 3.
inline constexpr int kExactRankPairs = 10;
double rankCorrelationP(double rho, int n);

// Holm's adjusted p-values, in the input's order: with the m defined values
// sorted ascending p(1) <= ... <= p(m), adj(i) = max over j <= i of
// min(1, (m - j + 1) p(j)). A test stands out at level alpha when adj < alpha.
// NaN entries are no tests: they stay NaN and do not count in m.
std::vector<double> holmAdjusted(std::span<const double> p);

}  // namespace c2d
