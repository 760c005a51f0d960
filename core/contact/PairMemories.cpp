#include "core/contact/PairMemories.h"

#include <algorithm>
#include <cmath>

#include "core/contact/CrushingLaw.h"
#include "core/contact/PairMotion.h"
#include "core/contact/PairStarts.h"
#include "core/contact/SpringFriction.h"

namespace c2d {

namespace {

// Held sides (the pairs of a ruptured joint), as fractions of the contact
// distance: a node this close to a segment is on it, a member whose far end
// is this close to the segment's line lies along it, and a held node this far
// clear of the line (or around the end) is let go.
constexpr double kOnSegment = 1e-6, kAlongLine = 1e-3, kLetGo = 0.25;

// The pair's boxes at the positions q alone are within contact distance
// (plus slack): the energy at a committed state sees it.
bool reachesAt(const ContactPair& pair, const PairPositions& q, double slack) {
  Box seg = Box::point(q.a.x(), q.a.y());
  seg.add(q.b.x(), q.b.y());
  return Box::point(q.x.x(), q.x.y()).inflated(pair.h + slack).overlaps(seg);
}

}  // namespace

bool commitPair(const MemberPairLaw& law, const ContactPair& pair, const State& s,
                const PairMemory* m, const PairOutcome& o, double full, bool near,
                const PairPositions& q0, const PairPositions& q1, double slack, CommitTally& tally,
                PairMemory& next) {
  const MemberContactData& data = law.data();
  next = {pair.key(), 0.0, 0.0, o.stretch, contactDistance(pair, m), m ? m->side : 0};
  bool flipped = false;
  // The offset shrinks with the penetration at the full distance (never
  // while the pair presses on: its force and energy are unchanged).
  if (m) next.offset = std::min(m->offset, std::max(full, 0.0));
  if (o.p1 > 0) {
    const double plain = std::max(m ? m->q : 0.0, o.p1);
    // A turn inside the step: the peak the pair's mass came back from.
    next.q = near ? pairLoadingPoint(data, law.masses(), pair, s, q0, q1, heldSide(m, q0),
                                     pairReach(pair, m), endFaces(m), plain, o.p1)
                  : plain;
    tally.crushed += crushingEnergy(data.k, data.restitution, plain, o.p1) -
                     crushingEnergy(data.k, data.restitution, next.q, o.p1);
    const int was = near ? heldSide(m, q0) : 0;
    // A held side changes only past the centre line by the full distance.
    if (near && pairSide(q1) != was && (!next.side || o.p1 > pairReach(pair, m) + next.h)) {
      if (next.side) next.side = -next.side;
      // Seen from the new side the penetration is smaller (the loading point
      // kept, so that the energy only drops).
      const double seen = pairPenetration(q1, -was, pairReach(pair, m), endFaces(&next));
      tally.released += crushingEnergy(data.k, data.restitution, next.q, o.p1) -
                        crushingEnergy(data.k, data.restitution, next.q, seen);
      if (seen <= 0) next.q = 0;
      ++tally.pushed;
      flipped = true;
    }
  }
  // A held side is let go once the node has cleared the centre line on it
  // by kLetGo of the contact distance, or gone as far around the end (from
  // then on the side at t_n is that side, and the contact distance it has
  // gained keeps it there), and when the offset is gone.
  const bool wasHeld = next.side != 0;
  if (next.side && (!near || next.offset <= 0 ||
                    pairPenetration(q1, next.side, 0.0, next.h) < -kLetGo * next.h))
    next.side = 0;
  // A held node can press on beyond the reach of the pair's boxes at the
  // committed positions alone (far on the wrong side beyond an end), where
  // the energy at the committed state does not see it.
  const bool nearAfter = near && reachesAt(pair, q1, slack);
  const bool kept = next.q > 0 || next.offset > 0 || next.stretch != 0;
  // Its energy at the committed state (as the energy there finds it).
  const double after =
      kept && nearAfter
          ? crushingEnergy(data.k, data.restitution, next.q,
                           pairPenetration(q1, heldSide(&next, q1), pairReach(pair, &next),
                                           endFaces(&next))) +
                springFrictionEnergy(data.k, next.stretch)
          : 0.0;
  tally.stored += after;
  // What a held pair stored at the end of the step and does not store so
  // seen from its new side, or apart, is released (the trial energy counted
  // it; a pushed pair booked its own above). From the loading point it gets
  // now: what the new loading point took is in `crushed` already (taken
  // from the memory's, it was booked twice).
  if (wasHeld && !flipped)
    tally.letGo += crushingEnergy(data.k, data.restitution, next.q, o.p1) +
                   springFrictionEnergy(data.k, o.stretch) - after;
  return kept;
}

double memorySlack(const ContactSearch& search, const Model& model,
                   const std::vector<PairMemory>& memory) {
  // Pairs in memory keep the contact distance they met at: the candidates'
  // boxes reach as far as the largest excess over the present distances.
  double slack = 0;
  for (const PairMemory& m : memory) {
    const int node = static_cast<int>(m.key >> 32), element = static_cast<int>(m.key & 0xffffffffu);
    if (node < search.numNodes() && element < model.numElements() && model.hasElement(element))
      slack = std::max(slack, m.h - search.nodeRadius(node) - search.radius(element));
  }
  return slack;
}

void openPairs(ContactSearch& search, const Model& model, State& s,
               std::vector<PairMemory>& fresh) {
  // Room for four pairs in contact per node before a commit must allocate.
  const std::size_t room = 4 * search.contactNodes().size();
  if (s.pairs.capacity() < room) s.pairs.reserve(room);
  if (fresh.capacity() < room) fresh.reserve(room);
  PairPositions q0, q1;
  // The new pairs gathered apart: appended to the memory they would unsort
  // it for the lookups of the pairs after them.
  fresh.clear();
  for (const ContactPair& pair : search.candidates(model, s)) {
    if (pairMemory(s, pair.key()) || !pairPositions(pair, model, s, q0, q1)) continue;
    // A node on the segment itself (a ruptured joint's end node, on the
    // centre line of the member it was joined to) has no side of its own.
    const bool onSegment = pairPenetration(q1, pairSide(q1), pair.h) >= (1 - kOnSegment) * pair.h;
    const int sd = onSegment ? membersSide(search, pair, model, s, q1) : 0;
    const double p = pairPenetration(q1, sd ? sd : pairSide(q1), pair.h, sd ? pair.h : 0.0);
    if (p <= 0) continue;
    fresh.push_back({pair.key(), 0.0, p, 0.0, pair.h, sd});
  }
  if (fresh.empty()) return;
  s.pairs.insert(s.pairs.end(), fresh.begin(), fresh.end());
  std::sort(s.pairs.begin(), s.pairs.end(),
            [](const PairMemory& a, const PairMemory& b) { return a.key < b.key; });
}

int membersSide(const ContactSearch& search, const ContactPair& pair, const Model& model,
                const State& s, const PairPositions& q) {
  // The far ends of the node's members (the elements at its joint group) seen
  // from the segment's line; members along the line tell nothing.
  const Vec2 t = q.b - q.a;
  const double l = t.norm();
  if (l == 0) return 0;
  int found = 0;
  for (int e : search.live()) {
    const auto nodes = model.element(e).nodes();
    for (int end = 0; end < 2; ++end) {
      if (search.group(nodes[end]) != search.group(pair.node)) continue;
      const int far = nodes[1 - end];
      const Vec2 x = model.coord(far) + Vec2(s.u[3 * far], s.u[3 * far + 1]);
      const double d = (t.x() * (x - q.a).y() - t.y() * (x - q.a).x()) / l;
      if (std::abs(d) <= kAlongLine * pair.h) continue;
      const int sd = d > 0 ? 1 : -1;
      if (found && sd != found) return 0;  // members on both sides
      found = sd;
    }
  }
  return found;
}

}  // namespace c2d
