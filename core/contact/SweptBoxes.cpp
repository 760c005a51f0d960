#include "core/contact/SweptBoxes.h"

#include <cmath>

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

const std::vector<int>& SweptBoxes::near(const State& s,
                                         const std::vector<ContactPair>& candidates, int version,
                                         double extra, double slack) {
  bool kept = version == nearVersion_ && extra == nearExtra_ && slack == nearSlack_ &&
              nearUn_.size() == s.un.size() && nearU_.size() == s.u.size() && nearUn_ == s.un;
  const double moved = 0.25 * slack;
  for (Eigen::Index i = 0; kept && i + 1 < s.u.size(); i += 3)
    kept = std::abs(s.u[i] - nearU_[i]) <= moved && std::abs(s.u[i + 1] - nearU_[i + 1]) <= moved;
  if (kept) return near_;
  // With the candidates' room: steps allocate nothing while the contacts
  // change little.
  if (near_.capacity() < candidates.capacity()) near_.reserve(candidates.capacity());
  near_.clear();
  for (std::size_t i = 0; i < candidates.size(); ++i)
    if (reach(candidates[i], extra + slack)) near_.push_back(static_cast<int>(i));
  nearU_ = s.u;
  nearUn_ = s.un;
  nearVersion_ = version;
  nearExtra_ = extra;
  nearSlack_ = slack;
  return near_;
}

}  // namespace c2d
