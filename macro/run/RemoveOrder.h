#pragma once
// REMOve,ELEMents,n1,n2,inc,td in a BATCh block: the elements it removes and
// the time over which their forces are released, read from its record.
#include <string>
#include <vector>

#include "macro/deck/Macro.h"
#include "macro/deck/Parameters.h"

namespace c2d {

struct RemoveOrder {
  std::vector<int> elements;  // 0-based (macro/run/CommandRange.h)
  double release = 0;         // td (0: at once)
  std::string error;          // why the command cannot run ("" when it can)
};

RemoveOrder readRemoveOrder(const Macro& m, const Parameters& params, int numElements);

}  // namespace c2d
