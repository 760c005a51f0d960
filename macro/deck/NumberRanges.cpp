#include "macro/deck/NumberRanges.h"

#include <cstdlib>

namespace c2d {

std::vector<int> generatedBetween(int l, int n, int ng) {
  std::vector<int> out;
  if (l == 0 || ng == 0) return out;
  const long long step = (n >= l ? 1 : -1) * std::llabs(static_cast<long long>(ng));
  for (long long k = l + step; step > 0 ? k < n : k > n; k += step)
    out.push_back(static_cast<int>(k));
  return out;
}

std::vector<int> steppedRange(int n1, int n2, int inc) {
  std::vector<int> out;
  if (inc <= 0) return out;
  for (long long k = n1; k <= n2; k += inc) out.push_back(static_cast<int>(k));
  return out;
}

long long firstBeyond(long long n1, long long n2, long long inc, long long count) {
  if (n2 <= count || inc <= 0) return 0;
  const long long first = n1 > count ? n1 : n1 + ((count - n1) / inc + 1) * inc;
  return first <= n2 ? first : 0;
}

}  // namespace c2d
