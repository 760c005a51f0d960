#pragma once
// The node and element numbers a record generates: FEAP's generation between
// two records (COORdinates, BOUNdary, FORCe, DISPlacement, FPROportional,
// MASS) and the stepped ranges n1, n1 + inc, ... <= n2 of QLOAd, BLASt,
// REMOve and the printing commands. Every step is taken in 64 bits, so that an
// increment near 2^31 ends the range instead of overflowing into numbers no
// deck gave.
#include <cstddef>
#include <vector>

namespace c2d {

// The numbers l+s, l+2s, ... strictly between l and n, s = sign(n - l) |ng|
// (none when l or ng is 0).
std::vector<int> generatedBetween(int l, int n, int ng);

// The first number n1 + k inc (k >= 0, inc > 0) above count that is at most
// n2, or 0 when the range n1..n2 stays within count: the first element a
// stepped range names beyond a mesh of count elements, found without
// generating the range.
long long firstBeyond(long long n1, long long n2, long long inc, long long count);

// The values of the generated numbers, interpolated linearly between xl (at l)
// and xn (at n): assign(k, value) for each.
template <class Assign, class Value>
void generateBetween(int l, int lg, int n, const Value& xl, const Value& xn, Assign assign) {
  const std::vector<int> ks = generatedBetween(l, n, lg);
  const double count = static_cast<double>(ks.size() + 1);
  for (std::size_t j = 0; j < ks.size(); ++j)
    assign(ks[j], xl + (xn - xl) * (static_cast<double>(j + 1) / count));
}

// n1, n1 + inc, ... up to n2 (inc > 0; none when n2 < n1).
std::vector<int> steppedRange(int n1, int n2, int inc);

}  // namespace c2d
