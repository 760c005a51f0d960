#include "core/contact/SweptBoxes.h"

#include <cmath>
#include <cstring>

namespace c2d {

void SweptBoxes::update(const Model& model, const State& s) {
  const int nn = model.numNodes();
  box_.resize(nn);
  const bool sized = nearUn_.size() == s.un.size() && nearU_.size() == s.u.size();
  // The positions at t_n the same to the bit as near()'s (memcmp: at every assembly).
  const bool same =
      sized && (s.un.size() == 0 ||
                std::memcmp(s.un.data(), nearUn_.data(),
                            sizeof(double) * static_cast<std::size_t>(s.un.size())) == 0);
  double moved = 0;
  for (int n = 0; n < nn; ++n) {
    // As pairPositions (core/contact/PairMotion.h) forms them, to the bit.
    const Vec2 x0 = nodePosition(model, s.un, n), x1 = nodePosition(model, s.u, n);
    Box b = Box::point(x0.x(), x0.y());
    b.add(x1.x(), x1.y());
    box_[n] = b;
    if (!sized) continue;
    // (A NaN stays: no list is kept for it.)
    for (const double d : {std::abs(s.u[3 * n] - nearU_[3 * n]),
                           std::abs(s.u[3 * n + 1] - nearU_[3 * n + 1])})
      if (d > moved || d != d) moved = d;
  }
  sameStart_ = same && 3 * static_cast<Eigen::Index>(nn) == s.un.size();
  moved_ = moved;
}

const std::vector<int>& SweptBoxes::near(const State& s,
                                         const std::vector<ContactPair>& candidates, int version,
                                         double extra, double slack) {
  const bool kept = version == nearVersion_ && extra == nearExtra_ && slack == nearSlack_ &&
                    sameStart_ && moved_ <= holds(slack);
  if (kept) return near_;
  // With the candidates' room: steps allocate nothing while the contacts
  // change little.
  if (near_.capacity() < candidates.capacity()) near_.reserve(candidates.capacity());
  near_.clear();
  for (std::size_t i = 0; i < candidates.size(); ++i)
    if (reach(candidates[i], extra + slack)) near_.push_back(static_cast<int>(i));
  nearU_ = s.u;
  nearUn_ = s.un;
  sameStart_ = true;
  moved_ = 0;
  nearVersion_ = version;
  nearExtra_ = extra;
  nearSlack_ = slack;
  ++listVersion_;
  return near_;
}

}  // namespace c2d
