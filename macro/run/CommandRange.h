#pragma once
// The numbers a printing or removing solution command selects (DISP, VELO,
// ACCE, REAC, STRE, REMOve): ALL (or no number) selects every one; n1,n2,inc
// the stepped range from n1 to n2 (n2 empty: n1 alone; inc empty or not
// positive: 1), clipped to 1..count.
#include <vector>

#include "macro/deck/Macro.h"
#include "macro/deck/Parameters.h"

namespace c2d {

// The selected numbers, 0-based, in increasing order.
std::vector<int> commandRange(const Macro& m, const Parameters& params, int count);

}  // namespace c2d
