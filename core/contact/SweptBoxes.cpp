#include "core/contact/SweptBoxes.h"

namespace c2d {

void SweptBoxes::update(const Model& model, const State& s) {
  const int nn = model.numNodes();
  box_.resize(nn);
  for (int n = 0; n < nn; ++n) {
    // As MemberContact::positions forms them, to the bit.
    const Vec2& X = model.coord(n);
    Box b = Box::point(X.x() + s.un[3 * n], X.y() + s.un[3 * n + 1]);
    b.add(X.x() + s.u[3 * n], X.y() + s.u[3 * n + 1]);
    box_[n] = b;
  }
}

}  // namespace c2d
