#pragma once
// What a member contact pair carries from one step to the next (State::pairs;
// docs/design/member-contact.md): its loading point, friction stretch,
// shrinking offset, the contact distance it met at and a held side. Found at a
// commit from the pair's step, and for the pairs set free inside their
// contact distance (the pieces of a ruptured joint) when the contact starts
// or the topology changes.
#include <vector>

#include "core/contact/ContactPair.h"
#include "core/contact/ContactSearch.h"
#include "core/contact/MemberPairLaw.h"
#include "core/contact/PairContact.h"
#include "core/Model.h"
#include "core/State.h"

namespace c2d {

// What a commit found over the pairs.
struct CommitTally {
  double released = 0;  // stored from an old side that a pushed pair no longer sees
  double letGo = 0;     // stored by a held pair and no more once let go (or apart)
  double crushed = 0;   // taken by a loading point moved to the peak of a turn
  double stored = 0;    // stored at the committed state
  int pushed = 0;       // pairs pushed past the segment's centre line
};

// The pair's memory after its step (next; true: kept), from its memory at t_n
// (m), the step's outcome o and its penetration at the full contact distance
// (full); q0 and q1 its positions, near: its swept boxes within reach (plus
// slack, the most a memory reaches beyond its pair's contact distance).
bool commitPair(const MemberPairLaw& law, const ContactPair& pair, const State& s,
                const PairMemory* m, const PairOutcome& o, double full, bool near,
                const PairPositions& q0, const PairPositions& q1, double slack, CommitTally& tally,
                PairMemory& next);

// The most a pair in memory reaches beyond its present contact distance.
double memorySlack(const ContactSearch& search, const Model& model,
                   const std::vector<PairMemory>& memory);

// The candidates at s now free to contact that are already inside their
// contact distance and have no memory get the offset of their present
// penetration (they start at zero force), into s.pairs; fresh: scratch.
void openPairs(ContactSearch& search, const Model& model, State& s,
               std::vector<PairMemory>& fresh);

// The side of the pair's segment (at the positions q) where the node's
// members lie, or 0 where they lie on both sides or along it.
int membersSide(const ContactSearch& search, const ContactPair& pair, const Model& model,
                const State& s, const PairPositions& q);

}  // namespace c2d
