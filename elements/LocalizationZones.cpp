#include "elements/LocalizationZones.h"

#include <cmath>

#include "elements/Joints.h"
#include "elements/ReissnerFrame.h"

namespace c2d {

namespace {

// Two elements at a node continue one member when their axes (reference
// configuration) are in line within this cosine (about 8 degrees).
constexpr double kInLine = 0.99;

ReissnerFrame* midpointFrame(Element& e) {
  auto* r = dynamic_cast<ReissnerFrame*>(&innermost(e));
  if (!r || !r->bendingLaw().hasHinge() || r->bendingLaw().site() != HingeSite::Midpoint)
    return nullptr;
  return r;
}

}  // namespace

double zoneLength(const MaterialSet& mat) {
  if (!mat.softening) return 0;
  if (mat.softening->pieceLength > 0) return mat.softening->pieceLength;
  return mat.section ? mat.section->h : 0.0;
}

int LocalizationZones::hold(Model& model) {
  const int ne = model.numElements(), nn = model.numNodes();
  frame_.assign(ne, nullptr);
  bool anyZone = false;
  for (int e = 0; e < ne; ++e)
    if (model.hasElement(e) && (frame_[e] = midpointFrame(model.element(e)))) {
      frame_[e]->setHeld(false);
      const MaterialSet* mat = model.material(frame_[e]->materialNumber());
      anyZone = anyZone || (mat && zoneLength(*mat) > 0);
    }
  if (!anyZone) return 0;
  // Per node: the elements whose innermost element holds it (a joint's slave
  // is the jointed element's node, so a joint ends the member it cuts; a
  // member that goes on through a joint's master, as a column through a
  // connection whose beam has a joint, is not cut).
  first_.assign(nn, -1);
  second_.assign(nn, -1);
  count_.assign(nn, 0);
  for (int e = 0; e < ne; ++e)
    if (model.hasElement(e))
      for (int n : innermost(model.element(e)).nodes()) {
        (count_[n] == 0 ? first_[n] : second_[n]) = e;
        ++count_[n];
      }
  held_.assign(ne, 0);
  const auto axis = [&](int e) {
    const auto n = innermost(model.element(e)).nodes();
    return (model.coord(n[1]) - model.coord(n[0])).normalized();
  };
  // The member's next element past element e's node n (-1: the member ends).
  const auto next = [&](int e, int n) {
    if (count_[n] != 2) return -1;
    const int f = first_[n] == e ? second_[n] : first_[n];
    if (f == e || !frame_[f] || std::abs(axis(e).dot(axis(f))) < kInLine) return -1;
    return f;
  };
  // Holds the member's elements from element f on, entered at its node n at
  // the distance reach (m) from the zone's origin, while their midpoints lie
  // nearer than zone.
  const auto holdFrom = [&](int f, int n, double reach, double zone) {
    for (int e = f; e >= 0; e = next(e, n)) {
      if (reach + 0.5 * frame_[e]->length() >= zone) break;
      held_[e] = 1;
      reach += frame_[e]->length();
      const auto en = innermost(model.element(e)).nodes();
      n = en[0] == n ? en[1] : en[0];
    }
  };
  const auto zoneOf = [&](int e) {
    const MaterialSet* mat = model.material(frame_[e]->materialNumber());
    return mat ? zoneLength(*mat) : 0.0;
  };
  for (int h = 0; h < ne; ++h) {
    if (!frame_[h]) continue;
    const double zone = zoneOf(h);
    if (!(zone > 0)) continue;
    const auto nodes = innermost(model.element(h)).nodes();
    for (int side = 0; side < 2; ++side) {
      const int n = nodes[side];
      if (frame_[h]->section().hingeActive)  // an open hinge: from its midpoint
        holdFrom(next(h, n), n, 0.5 * frame_[h]->length(), zone);
      // An end that carries no moment: the element alone holds the node, its
      // rotation is free and no nodal moment loads it (a free or pinned end,
      // or a joint's node: the joint carries none).
      // (count_ counts a joint's slave and master as nodes of their own
      // elements: a joint's node held by one element is such an end.)
      if (freeEnd(model, n, count_[n])) holdFrom(h, n, 0.0, zone);
    }
  }
  int count = 0;
  for (int e = 0; e < ne; ++e)
    if (frame_[e] && held_[e] && !frame_[e]->section().hingeActive) {
      frame_[e]->setHeld(true);
      ++count;
    }
  return count;
}

}  // namespace c2d
