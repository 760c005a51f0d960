#pragma once
// Penalty contact between members (CONTact record MEMBers,,k[,zeta[,r[,mu[,e]]]]):
// every node against every element segment it does not belong to, with the
// ground's crushing law (restitution e, core/contact/CrushingLaw.h) and elastic-plastic
// friction (mu, core/contact/SpringFriction.h) per pair.
//
// Geometry of a pair: node x, segment a-b (translations only), contact distance
// h = r_node + r_segment, with an element's contact radius r = sqrt(3 I / A)
// (half the depth of the rectangle with the section's A and I), or the record's
// radius when the material gives no section; a node's radius is the largest of
// its elements'. The penetration is
//   p = h - s d     where the node projects inside the segment, d the signed
//                   distance from the line a->b (positive to the left) and s the
//                   side the node was on at t_n (two-sided segments: a node
//                   pushed through the centre line is pushed back to its side),
//   p = h - |x - a| (or |x - b|) beyond the ends (rounded ends),
// and the stored energy U = k <p>^2 / 2 (the crushing law's energy for e < 1:
// each pair keeps its loading point q while in contact, State::pairs). p is
// continuous and its gradient too,
// except where a node that went through the centre line leaves the segment's
// span. At a vertex of a polyline the rounded end of one segment and the side of
// its neighbour both push a node within sqrt(2 h p) of the vertex: there the
// contact is up to twice as stiff.
//
// A node that ends a step in contact past the centre line is seen from its new
// side from then on: the energy its old side stored is released (booked in the
// energy account, counted and logged: the contact was too soft for the impact).
//
// Friction acts on the node's position along the segment, c = r1.r2 / |r2|
// (measured from a): a spring of stiffness k anchored where the pair last slid
// (its stretch kept per pair), sliding at mu N with N the pair's normal force
// (without the dissipative term); under the mid-point scheme the force is the
// law's path work over the step through the discrete gradient of c. Beyond the
// segment's ends it still acts along the segment.
//
// Excluded pairs: the elements at the node, the elements at the nodes tied to
// it by joints (a joint's master and slave are one node for contact), and pairs
// already within contact distance in the reference configuration (members
// meeting at a frame joint: parts of one piece of structure) while the members
// between them hold: while the node is as few elements from the segment as in
// the original mesh, joints counted as one node and ruptured ones as broken.
// A pair set free inside its contact distance (a joint ruptured; contact
// switched on at a deformed state) gets an offset o, its penetration then,
// and contacts at the distance h - o, the offset shrinking as the two move
// apart: it starts at zero force and the full distance returns once apart.
// A node set free on the segment itself (a ruptured joint's end node lies on
// the centre line of the member it was joined to, where its own side is a
// toss-up) is held on the side where its own members lie (the far ends of its
// elements), until it has cleared the centre line on that side or gone
// around the segment's end: held, it is pushed back from the wrong side also
// beyond the ends, by p = h + (d^2 - e^2) / rho (e the distance beyond the
// end, rho the distance from the end point: continuous in value and slope
// with the span's h + |d| and with the rounded end's h - rho across the line,
// where the pieces of a ruptured joint lie end to end), and a commit does not
// turn it to the wrong side unless it went through by the full distance.
// Inside the span it also meets the segment's end faces: its penetration
// grows with its distance into the span from the nearer end (up to the full
// contact distance), so that pieces pressed end to end bear on each other
// instead of sliding their tips past each other (core/contact/PairContact.cpp
// endFace).
// (Seen from its side at t_n, a node that the first step took a hundredth of
// a millimetre past the line was held on the wrong side from then on, and the
// pieces of a ruptured joint ended crossed.)
//
// Forces: under the static and Newmark rules the gradient of U at t_n+1; under
// the mid-point scheme a discrete gradient, so that an impact conserves energy
// exactly: with z = (x - a, b - a) (translation invariant: the forces sum to
// zero and linear momentum is conserved),
//   f_z = phi'(p_n, p_n+1) D,   D = grad p(z_m) + (p_n+1 - p_n - grad p(z_m).dz) dz / |dz|^2,
// phi' the closed-form discrete derivative of k <p>^2 / 2 (as the ground's), or
// the crushing law's work over the step divided by p_n+1 - p_n, so that
// f_z.dz = U_n+1 - U_n (+ what crushing dissipated), plus the dashpot's force
// along D (core/contact/ContactDamper.h: zeta's coefficient for the pair's reduced mass,
// core/contact/PairMotion.h; Newmark: c dp/dt grad p at t_n+1). A pair whose turn falls
// inside a step gets the peak its mass came back from as its loading point
// (core/contact/CrushingLaw.h crushingLoadingPoint), as a ground node does.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/contact/ContactGrid.h"
#include "core/contact/ContactMotion.h"
#include "core/contact/ContactPair.h"
#include "core/contact/PairContact.h"
#include "core/contact/SweptBoxes.h"
#include "core/DofMap.h"
#include "core/Model.h"
#include "core/State.h"
#include "core/StepRule.h"

namespace c2d {

// For every node: the representative of the nodes tied to it by joints.
std::vector<int> jointGroups(const Model& model);

// An element's contact radius from its section, sqrt(3 I / A) (half the depth
// of the rectangle with the section's A and I); 0 without a section.
double sectionRadius(const Model& model, int element);

class MemberContact {
 public:
  // Per topology version: contact nodes (used, not aliased), radii, joint
  // groups, the pairs excluded by the reference configuration.
  MemberContact(const Model& model, const DofMap& dofs);

  // Every pair that may carry a force at the state s (swept boxes from t_n to
  // t_n+1, inflated by the contact distance, overlap), and more: the list is
  // found with boxes inflated by a margin and kept while no node has moved
  // beyond its box of that search by more than the margin. Sorted by key.
  // Changes only when candidatesVersion() does. Forms the nodes' swept boxes
  // at s on the way (what sweptReach() reads).
  const std::vector<ContactPair>& candidates(const Model& model, const State& s) const;
  int candidatesVersion() const { return candidatesVersion_; }

  // Force and tangent of the candidate pair `index` of the last nearby(), at
  // its state s (false: no force), with the pair's memory in s.pairs. What
  // the pair's step start gives (its memory, side, reach, penetration at
  // t_n and law) is found at its first evaluation in the step and kept over
  // the step's iterations (nearby() tells when the start changes).
  bool evaluate(int index, const Model& model, const State& s, const StepRule& rule,
                bool wantTangent, PairVec& force, PairMat& tangent) const;

  // Stored energy at the trial state s (sides and memory from its committed
  // state), and the energy the crushing and the dissipative term took over the
  // step from t_n to t_n+1.
  double energy(const Model& model, const State& s) const;
  double dissipation(const Model& model, const State& s, const StepRule& rule) const;
  // The motion over the step to s of every pair that touches at either end
  // (core/contact/ContactMotion.h), appended to out.
  void motions(const Model& model, const State& s, std::vector<ContactMotion>& out) const;

  // At a commit: the memory of every pair in contact at the end of the step
  // (its loading point, friction stretch and shrinking offset) into s.pairs.
  // Returns the energy released: a pair whose node ended the step past the
  // segment's centre line is seen from its new side from then on, and the
  // energy it stored from the old side is gone (its force pushed the node on);
  // `pushed` counts such pairs, `pushedEnergy` adds what they released. So is
  // what a held pair stored and stores no more once let go (or apart).
  double commit(const Model& model, State& s, int& pushed, double& pushedEnergy) const;
  // The stored energy at the committed state s: as found by this contact's
  // last commit (no pass over the pairs), or evaluated when it made none.
  double committedEnergy(const Model& model, const State& s) const {
    return committed_ ? committedEnergy_ : energy(model, s);
  }
  // When the contact starts or the topology changes (s committed): a pair now
  // free to contact that is already inside its contact distance (the pieces of
  // a joint that ruptured) and has no memory gets the offset of its present
  // penetration, so that it starts at zero force.
  void openPairs(const Model& model, State& s) const;
  // The side of the pair's segment (at the positions q) where the node's
  // members lie, or 0 where they lie on both sides or along it.
  int membersSide(const ContactPair& pair, const Model& model, const State& s,
                  const PairPositions& q) const;

  // The pair's swept boxes are within contact distance plus `extra` at s.
  // The pair's boxes at the positions q alone are within contact distance
  // (plus the slack of its memory): energy() at a committed state sees it.
  bool reachesAt(const ContactPair& pair, const PairPositions& q) const {
    Box seg = Box::point(q.a.x(), q.a.y());
    seg.add(q.b.x(), q.b.y());
    return Box::point(q.x.x(), q.x.y()).inflated(pair.h + slack_).overlaps(seg);
  }
  // The candidates at s; those (indices, ascending) whose swept boxes over
  // the step to s may come within their contact distance plus extra (reach: a
  // superset, kept over a step's iterations while the nodes move little,
  // core/contact/SweptBoxes.h); and of these the ones that may touch (near:
  // all but the pairs that neither touch at t_n nor can come to touch while
  // the list holds, see mayTouch). evaluate() finds no force on a pair of
  // reach that is not near. sweptReach() is the exact test of one of them,
  // at the state of the last call.
  struct Nearby {
    const std::vector<ContactPair>& candidates;
    const std::vector<int>& reach;
    const std::vector<int>& near;
  };
  Nearby nearby(const Model& model, const State& s, double extra) const;
  bool sweptReach(const ContactPair& pair, double extra) const { return swept_.reach(pair, extra); }

  // The pair comes within extra of touching over the step to s: its
  // penetration, as evaluate() sees it, exceeds -extra at t_n or t_n+1.
  bool within(const ContactPair& pair, const Model& model, const State& s, double extra) const;

  double margin() const { return margin_; }
  // The most a pair's memory reaches beyond its contact distance: evaluate()
  // sees a pair whose swept boxes are within its distance plus this.
  double slack() const { return slack_; }
  // An assembly under `rule` is made (the rule the friction stretches of its
  // trial state belong to, as evaluate() notes it), its nearby() list of
  // pairs within reach empty or not (evaluate() notes the rule of every one).
  void assembling(const StepRule& rule, bool reached) const {
    if (reached || lastRule_.scheme != rule.scheme || lastRule_.alpha != rule.alpha)
      lastRule_ = rule;
  }
  double radius(int element) const { return elementRadius_[element]; }

 private:
  // The candidates found afresh around the nodes' swept boxes (swept_, just formed).
  void search(const Model& model) const;
  // The candidates hold for the nodes' swept boxes (swept_, just formed): no
  // node has left its box of the last search by more than the margin.
  bool valid() const;
  // The pair's positions at t_n and t_n+1, and whether its swept boxes are
  // within contact distance (plus extra).
  bool positions(const ContactPair& pair, const Model& model, const State& s, PairPositions& q0,
                 PairPositions& q1, double extra = 0) const;
  bool excluded(int node, int element, const Model& model) const;
  // The pair's memory at the last commit (null: none).
  static const PairMemory* memory(const State& s, std::uint64_t key);
  // The step at s under the rule of the candidate `index` of the last
  // nearby() (and its penetration at the full contact distance, without
  // offset, at t_n+1).
  PairOutcome outcome(int index, const Model& model, const State& s, const StepRule& rule,
                      double* full = nullptr) const;
  // outcome() of every pair touching() at s under rule, with its penetration at the
  // full distance: a commit reads them three times at one state (the energy
  // account's energy() and dissipation(), then commit()), so they are found once and kept while the
  // candidates, the state's displacements, rates and pair memory and the rule
  // are those they were found for.
  struct StepOutcome {
    int index = -1;  // the pair's in candidates()
    PairOutcome outcome;
    double full = 0;
  };
  const std::vector<StepOutcome>& outcomes(const Model& model, const State& s,
                                           const StepRule& rule) const;
  // The candidates that may touch over the step to s (nearby()'s near list,
  // with swept boxes within their distance plus the slack: positions() true)
  // or have a memory (indices, ascending): the passes over the pairs at a
  // commit visit these alone, the others having no force, energy or memory
  // (the main example's pile: 2600 candidates, 300-450 of these).
  const std::vector<int>& touching(const Model& model, const State& s) const;
  static double distance(const ContactPair& pair, const PairMemory* m) { return m ? m->h : pair.h; }
  // The side the node is held on: the memory's, or the one it was on at t_n.
  static int side(const PairMemory* m, const PairPositions& q0) {
    return m && m->side ? m->side : pairSide(q0);
  }
  // A held pair's end faces scale with the contact distance it met at (0: not
  // held; core/contact/PairContact.h).
  static double face(const PairMemory* m) { return m && m->side ? m->h : 0.0; }
  static double reach(const ContactPair& pair, const PairMemory* m) {
    return m ? m->h - m->offset : pair.h;
  }
  // What a candidate keeps over a step's iterations (evaluate(), outcome(), motions()).
  struct PairStart {
    int version = -1;  // the startVersion_ it was found at
    PairMemory memory;
    bool remembered = false;  // memory holds the pair's
    PairPositions q0;
    int side = 0;
    double reach = 0, face = 0, p0 = 0;
    PairZ z0 = PairZ::Zero();
    bool lawFound = false;  // law and mass formed
    PairLaw law;
    double mass = 0;  // the pair's (core/contact/PairMotion.h)
  };
  // The candidate `index` (of the last nearby(), at s) may touch while each
  // of its nodes moves by at most `move` from its position at s: it touches
  // at t_n, or has a memory (a held side, end faces, a contact distance of
  // its own), or at s lies closer than its contact distance h plus 2.5 move,
  // or across its segment's line from its side at t_n, or its segment is
  // shorter than 4 move or h shorter than 2.5 move. Otherwise its
  // penetration stays below -move / 2: the distance from the node to the
  // segment changes by at most 2 move, and its signed distance from the
  // segment's line too, so that the node cannot reach the span on the line's
  // other side (where the penetration is h plus that distance).
  bool mayTouch(int index, const Model& model, const State& s, double move) const;
  // The kept step start of the candidate `index` of the last nearby() at s
  // (found now when not kept), and its law.
  PairStart& startOf(int index, const Model& model, const State& s) const;
  void formLaw(PairStart& start, const ContactPair& pair, const State& s) const;
  // The pair's law at s (its dashpot for the masses at t_n: q0).
  PairLaw law(const ContactPair& pair, const State& s, const PairPositions& q0,
              const PairMemory* m) const;

  MemberContactData data_;
  std::vector<int> contactNodes_;                 // used and not aliased
  std::vector<char> usedNode_;                    // nodes whose motion matters (in some element)
  std::vector<double> elementRadius_;             // per element
  std::vector<double> nodeRadius_;                // per node
  std::vector<double> masses_;                    // per node (core/NodeMass.h)
  std::vector<int> group_;                        // joint groups
  std::vector<std::uint64_t> referenceExcluded_;  // sorted pair keys
  double margin_ = 0;

  // The search and its cache (a function of the state; rebuilt on demand).
  mutable ContactGrid grid_;
  std::vector<int> live_;  // the elements in the model (removed ones are not)
  mutable std::vector<Box> boxes_;  // per entry of live_
  mutable std::vector<Box> anchor_;  // per node: its swept box at the last search
  mutable std::vector<ContactPair> candidates_;
  mutable std::vector<PairMemory> nextMemory_;  // commit's scratch
  mutable SweptBoxes swept_;                    // nearby()
  mutable std::vector<PairStart> start_;  // per candidate
  // The step start the kept ones belong to: changes with the candidates and
  // the state's positions, rates and pair memory at t_n.
  mutable int startVersion_ = 0, startCandidates_ = -1;
  mutable Eigen::VectorXd startUn_, startVn_, startAn_;
  mutable std::vector<PairMemory> startPairs_;
  // nearby()'s pairs that may touch, and the list of SweptBoxes and the step
  // start they were found for.
  mutable std::vector<int> near_;
  mutable int nearList_ = -1, nearStart_ = -1;
  mutable std::vector<int> touching_;           // touching()'s
  // outcomes() and what they were found for.
  mutable std::vector<StepOutcome> outcomes_;
  mutable bool outcomesValid_ = false;
  mutable int outcomesVersion_ = -1;
  mutable StepRule outcomesRule_;
  mutable double outcomesSlack_ = 0;
  mutable Eigen::VectorXd outcomesU_, outcomesUn_, outcomesVn_, outcomesAn_;
  mutable std::vector<PairMemory> outcomesPairs_;
  // The rule of the last evaluation: the friction springs' stretches at a
  // trial state are those of the step that was assembled (as the ground's).
  mutable StepRule lastRule_;
  mutable double committedEnergy_ = 0;
  mutable bool committed_ = false;  // committedEnergy_ is that of a commit
  mutable double slack_ = 0;        // the most a pair's memory reaches beyond its distance
  mutable int candidatesVersion_ = 0;
  mutable bool searched_ = false;
};

// Inline: evaluated for every candidate at every assembly.
inline bool MemberContact::positions(const ContactPair& pair, const Model& model, const State& s,
                              PairPositions& q0, PairPositions& q1, double extra) const {
  q0 = {nodePosition(model, s.un, pair.node), nodePosition(model, s.un, pair.a),
        nodePosition(model, s.un, pair.b)};
  q1 = {nodePosition(model, s.u, pair.node), nodePosition(model, s.u, pair.a),
        nodePosition(model, s.u, pair.b)};
  Box node = Box::point(q0.x.x(), q0.x.y()), seg = Box::point(q0.a.x(), q0.a.y());
  node.add(q1.x.x(), q1.x.y());
  seg.add(q0.b.x(), q0.b.y());
  seg.add(q1.a.x(), q1.a.y());
  seg.add(q1.b.x(), q1.b.y());
  return node.inflated(pair.h + extra).overlaps(seg);
}

}  // namespace c2d
