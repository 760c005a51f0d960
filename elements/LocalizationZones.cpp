#include "elements/LocalizationZones.h"

#include <cmath>
#include <vector>

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

int holdLocalizationZones(Model& model) {
  const int ne = model.numElements();
  std::vector<ReissnerFrame*> frame(ne, nullptr);
  // Per node: the elements whose innermost element holds it (a joint's slave
  // is the jointed element's node: a joint ends the member).
  std::vector<std::vector<int>> at(model.numNodes());
  bool anyOpen = false;
  for (int e = 0; e < ne; ++e) {
    if (!model.hasElement(e)) continue;
    for (int n : innermost(model.element(e)).nodes()) at[n].push_back(e);
    frame[e] = midpointFrame(model.element(e));
    if (frame[e]) anyOpen = anyOpen || frame[e]->section().hingeActive;
  }
  std::vector<char> jointNode(model.numNodes(), 0), held(ne, 0);
  for (const Joint& j : model.joints()) jointNode[j.master] = jointNode[j.slave] = 1;
  const auto axis = [&](int e) {
    const auto n = innermost(model.element(e)).nodes();
    return (model.coord(n[1]) - model.coord(n[0])).normalized();
  };
  // The member's next element past element e's node n (-1: the member ends).
  const auto next = [&](int e, int n) {
    if (jointNode[n] || at[n].size() != 2) return -1;
    const int f = at[n][0] == e ? at[n][1] : at[n][0];
    if (f == e || !frame[f] || std::abs(axis(e).dot(axis(f))) < kInLine) return -1;
    return f;
  };
  for (int h = 0; anyOpen && h < ne; ++h) {
    if (!frame[h] || !frame[h]->section().hingeActive) continue;
    const MaterialSet* mat = model.material(frame[h]->materialNumber());
    const double zone = mat ? zoneLength(*mat) : 0.0;
    if (!(zone > 0)) continue;
    for (int side = 0; side < 2; ++side) {
      int e = h, n = innermost(model.element(h)).nodes()[side];
      double reach = 0.5 * frame[h]->length();  // from the hinge to node n
      for (int f = next(e, n); f >= 0; f = next(e, n)) {
        if (reach + 0.5 * frame[f]->length() >= zone) break;
        held[f] = 1;
        reach += frame[f]->length();
        const auto fn = innermost(model.element(f)).nodes();
        n = fn[0] == n ? fn[1] : fn[0];
        e = f;
      }
    }
  }
  int count = 0;
  for (int e = 0; e < ne; ++e)
    if (frame[e]) {
      const bool hold = held[e] && !frame[e]->section().hingeActive;
      frame[e]->setHeld(hold);
      count += hold;
    }
  return count;
}

}  // namespace c2d
