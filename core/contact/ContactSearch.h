#pragma once
// The member contact's search (docs/design/member-contact.md): the node-segment
// pairs that may touch. The candidates come from a grid of the elements' boxes
// around the nodes' swept boxes, inflated by a margin, and are kept while no
// node has left its box of that search by more than the margin; over a step,
// those within reach by their swept boxes (core/contact/SweptBoxes.h) and of
// these the ones that may touch (the near list).
#include <cstdint>
#include <vector>

#include "core/contact/ContactGrid.h"
#include "core/contact/ContactPair.h"
#include "core/contact/SweptBoxes.h"
#include "core/DofMap.h"
#include "core/Model.h"
#include "core/State.h"

namespace c2d {

// For every node: the representative of the nodes tied to it by joints.
std::vector<int> jointGroups(const Model& model);

// An element's contact radius: its material's RADIus when given, else from
// its section, sqrt(3 I / A) (half the depth
// of the rectangle with the section's A and I); 0 without a section.
double sectionRadius(const Model& model, int element);

class ContactSearch {
 public:
  // Per topology version: contact nodes (used, not aliased), radii (the
  // section's, else `radius` when >= 0, else a thousandth of the model's
  // characteristic length), joint groups, the pairs excluded by the
  // reference configuration.
  ContactSearch(const Model& model, const DofMap& dofs, double radius);

  // Every pair that may carry a force at the state s (swept boxes from t_n to
  // t_n+1, inflated by the contact distance, overlap), and more: the list is
  // found with boxes inflated by the margin and kept while no node has moved
  // beyond its box of that search by more than the margin. Sorted by key.
  // Changes only when version() does. Forms the nodes' swept boxes at s on
  // the way (what sweptReach() reads).
  const std::vector<ContactPair>& candidates(const Model& model, const State& s);
  // The candidates as last found.
  const std::vector<ContactPair>& candidates() const { return candidates_; }
  int version() const { return version_; }

  // The candidates (indices, ascending) whose swept boxes over the step to s
  // may come within their contact distance plus extra (SweptBoxes::near with
  // this slack), after candidates(s).
  const std::vector<int>& reach(const State& s, double extra, double slack) {
    return swept_.near(s, candidates_, version_, extra, slack);
  }
  // Of the reach() list, the pairs that may touch while it holds
  // (mayTouch(index)), found afresh when reach() found its list afresh, for
  // the step start `start`; under another step start, the reach list itself.
  template <class MayTouch>
  const std::vector<int>& near(const std::vector<int>& reach, int start, MayTouch&& mayTouch);
  // The pairs of the near list whose swept boxes are within their contact
  // distance plus slack, and the pairs in `memory` (sorted by key) that are
  // not: the pairs a commit's passes visit (indices, ascending).
  const std::vector<int>& touching(const std::vector<int>& near,
                                   const std::vector<PairMemory>& memory, double slack);
  // The pair's swept boxes at the last candidates() are within its contact
  // distance plus extra.
  bool sweptReach(const ContactPair& pair, double extra) const { return swept_.reach(pair, extra); }

  double margin() const { return margin_; }
  double radius(int element) const { return elementRadius_[element]; }
  double nodeRadius(int node) const { return nodeRadius_[node]; }
  int numNodes() const { return static_cast<int>(nodeRadius_.size()); }
  const std::vector<int>& contactNodes() const { return contactNodes_; }
  // The elements in the model (removed ones and braces are not).
  const std::vector<int>& live() const { return live_; }
  int group(int node) const { return group_[node]; }

 private:
  // The candidates found afresh around the nodes' swept boxes (swept_, just formed).
  void search(const Model& model);
  // The candidates hold for the nodes' swept boxes (swept_, just formed): no
  // node has left its box of the last search by more than the margin.
  bool valid() const;
  bool excluded(int node, int element, const Model& model) const;
  void excludeReferencePairs(const Model& model);

  std::vector<int> contactNodes_;                 // used and not aliased
  std::vector<char> usedNode_;                    // nodes whose motion matters (in some element)
  std::vector<double> elementRadius_;             // per element
  std::vector<double> nodeRadius_;                // per node
  std::vector<int> group_;                        // joint groups
  std::vector<std::uint64_t> referenceExcluded_;  // sorted pair keys
  std::vector<int> live_;
  double margin_ = 0;

  ContactGrid grid_;
  std::vector<Box> boxes_;   // per entry of live_
  std::vector<Box> anchor_;  // per node: its swept box at the last search
  std::vector<ContactPair> candidates_;
  int version_ = 0;
  bool searched_ = false;
  SweptBoxes swept_;
  // near()'s list, and the reach list and step start it was found for.
  std::vector<int> near_;
  int nearList_ = -1, nearStart_ = -1;
  std::vector<int> touching_;
};

template <class MayTouch>
const std::vector<int>& ContactSearch::near(const std::vector<int>& reach, int start,
                                            MayTouch&& mayTouch) {
  if (swept_.listVersion() != nearList_) {
    near_.clear();
    if (near_.capacity() < reach.capacity()) near_.reserve(reach.capacity());  // none in a step
    for (int i : reach)
      if (mayTouch(i)) near_.push_back(i);
    nearList_ = swept_.listVersion();
    nearStart_ = start;
  }
  return nearStart_ == start ? near_ : reach;
}

}  // namespace c2d
