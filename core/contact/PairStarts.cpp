#include "core/contact/PairStarts.h"

#include <algorithm>

namespace c2d {

const PairMemory* pairMemory(const State& s, std::uint64_t key) {
  const auto it = std::lower_bound(s.pairs.begin(), s.pairs.end(), key,
                                   [](const PairMemory& m, std::uint64_t k) { return m.key < k; });
  return it != s.pairs.end() && it->key == key ? &*it : nullptr;
}

void PairStarts::begin(const State& s, int version, const std::vector<ContactPair>& candidates) {
  const bool sameState = state_.same(s, false);
  if (sameState && candidates_ == version) return;
  ++version_;
  candidates_ = version;
  if (start_.size() < candidates.size()) start_.resize(candidates.capacity());
}

PairStart& PairStarts::of(int index, const ContactPair& pair, const Model& model, const State& s) {
  PairStart& start = start_[index];
  if (start.version == version_) return start;
  start.version = version_;
  const PairMemory* m = pairMemory(s, pair.key());
  start.remembered = m != nullptr;
  if (m) start.memory = *m;
  start.q0 = {nodePosition(model, s.un, pair.node), nodePosition(model, s.un, pair.a),
              nodePosition(model, s.un, pair.b)};
  start.side = heldSide(m, start.q0);
  start.reach = pairReach(pair, m);
  start.face = endFaces(m);
  PairStep step;
  pairStart(start.q0, start.side, start.reach, step, start.face);
  start.z0 = step.z0;
  start.p0 = step.p0;
  start.lawFound = false;
  return start;
}

bool mayTouch(const PairStart& start, const ContactPair& pair, const Model& model, const State& s,
              double move) {
  if (start.remembered || start.p0 > 0) return true;
  const Vec2 r1 = nodePosition(model, s.u, pair.node) - nodePosition(model, s.u, pair.a);
  const Vec2 r2 = nodePosition(model, s.u, pair.b) - nodePosition(model, s.u, pair.a);
  const double l2 = r2.squaredNorm(), h = start.reach;
  if (!(l2 > 16 * move * move) || !(h > 2.5 * move)) return true;
  const double d = start.side * (r2.x() * r1.y() - r2.y() * r1.x());  // on its side: > 0
  const double xi = std::clamp(r1.dot(r2) / l2, 0.0, 1.0);
  const double dist = (r1 - xi * r2).norm();
  return !(d > 0 && dist > h + 2.5 * move);
}

}  // namespace c2d
