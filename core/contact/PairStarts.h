#pragma once
// What each candidate pair of the member contact keeps from the start of a
// step (docs/design/member-contact.md): its memory, the side it is seen from,
// its reach and its penetration at t_n, found at its first evaluation in the
// step and kept over the step's iterations, and its law once it touches. The
// kept starts are dropped when the candidates or the state at t_n (positions,
// rates, pair memory) change.
#include <cstdint>
#include <vector>

#include "core/contact/ContactPair.h"
#include "core/contact/PairContact.h"
#include "core/contact/StateStamp.h"
#include "core/Model.h"
#include "core/State.h"

namespace c2d {

// The pair's memory at the last commit (null: none).
const PairMemory* pairMemory(const State& s, std::uint64_t key);
// What a memory m (null: none) makes of its pair: the contact distance it met at,
inline double contactDistance(const ContactPair& pair, const PairMemory* m) {
  return m ? m->h : pair.h;
}
// the side the node is held on (the memory's, or the one it was on at t_n: q0),
inline int heldSide(const PairMemory* m, const PairPositions& q0) {
  return m && m->side ? m->side : pairSide(q0);
}
// the contact distance a held pair's end faces scale with (0: not held;
// core/contact/PairContact.h),
inline double endFaces(const PairMemory* m) { return m && m->side ? m->h : 0.0; }
// and the distance at which it touches (less its offset).
inline double pairReach(const ContactPair& pair, const PairMemory* m) {
  return m ? m->h - m->offset : pair.h;
}

// A candidate's step start.
struct PairStart {
  int version = -1;  // the PairStarts::version() it was found at
  PairMemory memory;
  bool remembered = false;  // memory holds the pair's
  PairPositions q0;
  int side = 0;
  double reach = 0, face = 0, p0 = 0;
  PairZ z0 = PairZ::Zero();
  bool lawFound = false;  // law and mass formed (core/contact/MemberPairLaw.h)
  PairLaw law;
  double mass = 0;  // the pair's (core/contact/PairMotion.h)
  // The pair's memory (null: none).
  const PairMemory* remembers() const { return remembered ? &memory : nullptr; }
};

class PairStarts {
 public:
  // The step start of s for `candidates` (of the search's `version`): when
  // these or the state's positions, rates or pair memory at t_n differ from
  // the last call's, the kept starts are dropped (version() changes).
  void begin(const State& s, int version, const std::vector<ContactPair>& candidates);
  int version() const { return version_; }
  // The kept start of the candidate `index` (pair), found now when not kept.
  PairStart& of(int index, const ContactPair& pair, const Model& model, const State& s);

 private:
  std::vector<PairStart> start_;  // per candidate
  int version_ = 0, candidates_ = -1;
  StateStamp state_;
};

// The candidate pair (its start) may touch while each of its nodes moves by
// at most `move` from its position at s: it touches at t_n, or has a memory
// (a held side, end faces, a contact distance of its own), or at s lies
// closer than its contact distance h plus 2.5 move, or across its segment's
// line from its side at t_n, or its segment is shorter than 4 move or h
// shorter than 2.5 move. Otherwise its penetration stays below -move / 2:
// the distance from the node to the segment changes by at most 2 move, and
// its signed distance from the segment's line too, so that the node cannot
// reach the span on the line's other side (where the penetration is h plus
// that distance).
bool mayTouch(const PairStart& start, const ContactPair& pair, const Model& model, const State& s,
              double move);

}  // namespace c2d
