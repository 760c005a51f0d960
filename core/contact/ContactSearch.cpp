#include "core/contact/ContactSearch.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/Brace.h"
#include "core/contact/PairContact.h"

namespace c2d {

namespace {

// Joint groups merged further with the nodes at one reference position: the
// nodes of the original mesh (a joint that ruptured still joins its two nodes
// here).
std::vector<int> originalGroups(const Model& model, const std::vector<int>& groups) {
  const int nn = model.numNodes();
  std::vector<int> parent = groups, order(nn);
  auto find = [&](int n) {
    while (parent[n] != n) n = parent[n] = parent[parent[n]];
    return n;
  };
  std::iota(order.begin(), order.end(), 0);
  auto less = [&](int a, int b) {
    const Vec2 &x = model.coord(a), &y = model.coord(b);
    return x.x() < y.x() || (x.x() == y.x() && x.y() < y.y());
  };
  std::sort(order.begin(), order.end(), less);
  for (int i = 1; i < nn; ++i)
    if (!less(order[i - 1], order[i])) {
      const int a = find(order[i - 1]), b = find(order[i]);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  for (int n = 0; n < nn; ++n) parent[n] = find(n);
  return parent;
}

// The node groups joined by the live elements.
class GroupGraph {
 public:
  GroupGraph(const Model& model, const std::vector<int>& live, std::vector<int> group)
      : model_(model), group_(std::move(group)), start_(group_.size() + 1, 0) {
    for (int e : live)
      for (int n : model.element(e).nodes()) ++start_[group_[n] + 1];
    for (std::size_t g = 1; g < start_.size(); ++g) start_[g] += start_[g - 1];
    elements_.resize(start_.back());
    std::vector<int> fill(start_.begin(), start_.end() - 1);
    for (int e : live)
      for (int n : model.element(e).nodes()) elements_[fill[group_[n]]++] = e;
  }
  // Elements on the shortest path from node n's group to a node of element e
  // (0: e has a node in it), counted up to maxHops; beyond: maxHops + 1.
  int hops(int n, int e, int maxHops) const {
    const auto target = model_.element(e).nodes();
    std::vector<int> frontier{group_[n]}, seen{group_[n]}, next;
    for (int depth = 0; depth <= maxHops; ++depth) {
      for (int g : frontier)
        if (g == group_[target[0]] || g == group_[target[1]]) return depth;
      next.clear();
      for (int g : frontier)
        for (int i = start_[g]; i < start_[g + 1]; ++i)
          for (int m : model_.element(elements_[i]).nodes())
            if (std::find(seen.begin(), seen.end(), group_[m]) == seen.end()) {
              seen.push_back(group_[m]);
              next.push_back(group_[m]);
            }
      frontier.swap(next);
    }
    return maxHops + 1;
  }

 private:
  const Model& model_;
  std::vector<int> group_;
  std::vector<int> start_, elements_;
};

}  // namespace

double sectionRadius(const Model& model, int element) {
  const MaterialSet* m = model.material(model.element(element).materialNumber());
  if (m && m->contactRadius > 0) return m->contactRadius;
  return m && m->A > 0 && m->I > 0 ? std::sqrt(3 * m->I / m->A) : 0.0;
}

std::vector<int> jointGroups(const Model& model) {
  std::vector<int> parent(model.numNodes());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int n) {
    while (parent[n] != n) n = parent[n] = parent[parent[n]];
    return n;
  };
  for (const Joint& j : model.joints()) {
    const int a = find(j.master), b = find(j.slave);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
  for (int n = 0; n < model.numNodes(); ++n) parent[n] = find(n);
  return parent;
}

ContactSearch::ContactSearch(const Model& model, const DofMap& dofs, double radius) {
  const int nn = model.numNodes();
  for (int e = 0; e < model.numElements(); ++e)
    if (model.hasElement(e) && !isBrace(model.element(e))) live_.push_back(e);  // struts strike nothing
  const int ne = static_cast<int>(live_.size());
  group_ = jointGroups(model);
  usedNode_.assign(nn, 0);
  for (int n = 0; n < nn; ++n) {
    if (!dofs.used(n)) continue;
    usedNode_[n] = 1;
    if (!dofs.aliased(n)) contactNodes_.push_back(n);
  }
  const double shortest = model.characteristicLength();
  const double fallback = radius >= 0 ? radius : 1e-3 * shortest;
  elementRadius_.assign(model.numElements(), fallback);
  nodeRadius_.assign(nn, 0.0);
  double length = 0;
  for (int e : live_) {
    const Element& el = model.element(e);
    if (const double r = sectionRadius(model, e); r > 0) elementRadius_[e] = r;
    const auto nodes = el.nodes();
    length += (model.coord(nodes[0]) - model.coord(nodes[1])).norm();
    for (int n : nodes) nodeRadius_[n] = std::max(nodeRadius_[n], elementRadius_[e]);
  }
  // A node's contact radius is that of its joint group.
  for (int n = 0; n < nn; ++n)
    nodeRadius_[group_[n]] = std::max(nodeRadius_[group_[n]], nodeRadius_[n]);
  for (int n = 0; n < nn; ++n) nodeRadius_[n] = nodeRadius_[group_[n]];
  // The margin of the candidate search: half the mean element length.
  margin_ = ne > 0 ? 0.5 * length / ne : 1.0;
  excludeReferencePairs(model);
  anchor_.resize(nn);
}

void ContactSearch::excludeReferencePairs(const Model& model) {
  // Pairs within contact distance in the reference configuration.
  const int ne = static_cast<int>(live_.size());
  std::vector<Box> boxes(ne);
  for (int i = 0; i < ne; ++i) {
    const int e = live_[i];
    const auto nodes = model.element(e).nodes();
    Box b = Box::point(model.coord(nodes[0]).x(), model.coord(nodes[0]).y());
    b.add(model.coord(nodes[1]).x(), model.coord(nodes[1]).y());
    boxes[i] = b.inflated(elementRadius_[e]);
  }
  // Such a pair stays excluded while the members between them hold: while the
  // node is as few elements from the segment as in the original mesh (joints
  // that ruptured since are counted as broken), or when it was not within a
  // few elements of it there.
  ContactGrid grid;
  grid.build(boxes, 1e-6 * model.characteristicLength());
  const GroupGraph now(model, live_, group_), original(model, live_, originalGroups(model, group_));
  constexpr int kNearHops = 3;
  for (int n : contactNodes_) {
    const Vec2& x = model.coord(n);
    grid.query(Box::point(x.x(), x.y()).inflated(nodeRadius_[n]), [&](int i) {
      const int e = live_[i];
      if (excluded(n, e, model)) return;
      const auto nodes = model.element(e).nodes();
      const PairPositions q{x, model.coord(nodes[0]), model.coord(nodes[1])};
      const double h = nodeRadius_[n] + elementRadius_[e];
      // Without a side: the distance itself (p = h - |d| inside the span).
      if (pairPenetration(q, pairSide(q), h) <= 0) return;
      const int was = original.hops(n, e, kNearHops);
      if (was > kNearHops || now.hops(n, e, was) <= was)
        referenceExcluded_.push_back(ContactPair{n, e}.key());
    });
  }
  std::sort(referenceExcluded_.begin(), referenceExcluded_.end());
}

bool ContactSearch::excluded(int node, int element, const Model& model) const {
  for (int m : model.element(element).nodes())
    if (group_[m] == group_[node]) return true;
  return false;
}

bool ContactSearch::valid() const {
  if (!searched_) return false;
  for (int n = 0; n < static_cast<int>(usedNode_.size()); ++n) {
    if (!usedNode_[n]) continue;
    const Box& a = anchor_[n];
    const Box& b = swept_.box(n);
    if (b.x0 < a.x0 - margin_ || b.x1 > a.x1 + margin_ || b.y0 < a.y0 - margin_ ||
        b.y1 > a.y1 + margin_)
      return false;
  }
  return true;
}

void ContactSearch::search(const Model& model) {
  const int ne = static_cast<int>(live_.size());
  // The nodes' swept boxes at s (candidates() has just formed them).
  for (int n = 0; n < model.numNodes(); ++n)
    if (usedNode_[n]) anchor_[n] = swept_.box(n);
  boxes_.resize(ne);
  for (int i = 0; i < ne; ++i) {
    const int e = live_[i];
    const auto nodes = model.element(e).nodes();
    Box b = anchor_[nodes[0]];
    b.add(anchor_[nodes[1]].x0, anchor_[nodes[1]].y0);
    b.add(anchor_[nodes[1]].x1, anchor_[nodes[1]].y1);
    boxes_[i] = b.inflated(elementRadius_[e] + margin_);
  }
  grid_.build(boxes_, 1e-6 * margin_);
  candidates_.clear();
  for (int n : contactNodes_) {
    grid_.query(anchor_[n].inflated(nodeRadius_[n] + margin_), [&](int i) {
      const int e = live_[i];
      if (excluded(n, e, model)) return;
      const ContactPair key{n, e};
      if (std::binary_search(referenceExcluded_.begin(), referenceExcluded_.end(), key.key()))
        return;
      const auto nodes = model.element(e).nodes();
      candidates_.push_back({n, e, nodes[0], nodes[1], nodeRadius_[n] + elementRadius_[e]});
    });
  }
  std::sort(candidates_.begin(), candidates_.end(),
            [](const ContactPair& p, const ContactPair& q) { return p.key() < q.key(); });
  // Room for the list to double before a later search must allocate (steps
  // allocate nothing while the contacts change little).
  if (candidates_.capacity() < 2 * candidates_.size()) candidates_.reserve(2 * candidates_.size());
  searched_ = true;
  ++version_;
}

const std::vector<ContactPair>& ContactSearch::candidates(const Model& model, const State& s) {
  swept_.update(model, s);
  if (!valid()) search(model);
  return candidates_;
}

const std::vector<int>& ContactSearch::touching(const std::vector<int>& near,
                                                const std::vector<PairMemory>& memory,
                                                double slack) {
  const std::vector<ContactPair>& pairs = candidates_;
  touching_.clear();
  if (touching_.capacity() < pairs.capacity()) touching_.reserve(pairs.capacity());
  for (int i : near)
    if (swept_.reach(pairs[i], slack)) touching_.push_back(i);
  // The pairs in memory out of reach (a friction spring or a held side let
  // go), in key order as the candidates are.
  const auto within = static_cast<std::ptrdiff_t>(touching_.size());
  for (const PairMemory& m : memory) {
    const auto it = std::lower_bound(pairs.begin(), pairs.end(), m.key,
                                     [](const ContactPair& p, std::uint64_t k) { return p.key() < k; });
    if (it != pairs.end() && it->key() == m.key && !swept_.reach(*it, slack))
      touching_.push_back(static_cast<int>(it - pairs.begin()));
  }
  std::inplace_merge(touching_.begin(), touching_.begin() + within, touching_.end());
  return touching_;
}

}  // namespace c2d
