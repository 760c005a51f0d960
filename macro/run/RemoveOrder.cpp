#include "macro/run/RemoveOrder.h"

#include "macro/run/CommandRange.h"

namespace c2d {

RemoveOrder readRemoveOrder(const Macro& m, const Parameters& params, int numElements) {
  RemoveOrder order;
  order.elements = commandRange(m, params, numElements);
  if (order.elements.empty()) {
    order.error = "no element in the range";
    return order;
  }
  order.release = m.has(3) && !m.record.text(5).empty() ? m.numbers[3].eval(params) : 0.0;
  if (!(order.release >= 0)) order.error = "the release time td must be zero or positive";
  return order;
}

}  // namespace c2d
