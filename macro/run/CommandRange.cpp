#include "macro/run/CommandRange.h"

#include <algorithm>

#include "macro/deck/NumberRanges.h"

namespace c2d {

std::vector<int> commandRange(const Macro& m, const Parameters& params, int count) {
  std::vector<int> out;
  const bool all = m.option == "all" || m.numbers.empty() || m.record.text(2).empty();
  if (all) {
    for (int i = 0; i < count; ++i) out.push_back(i);
    return out;
  }
  const int n1 = m.numbers[0].evalInt(params, "first number");
  int n2 =
      m.has(1) && !m.record.text(3).empty() ? m.numbers[1].evalInt(params, "last number") : n1;
  int inc = m.has(2) && !m.record.text(4).empty() ? m.numbers[2].evalInt(params, "increment") : 1;
  if (inc <= 0) inc = 1;
  for (int i : steppedRange(std::max(n1, 1), std::min(n2, count), inc)) out.push_back(i - 1);
  return out;
}

}  // namespace c2d
