// RIGId: rigid end zones of frame elements (elements/RigidEnds.h), records
// 'e offset1 offset2' up to a blank record. The offsets are checked at their
// record; the element is rebuilt with them once the mesh input has built it.
#include <iomanip>
#include <ostream>
#include <stdexcept>

#include "elements/ElementFactory.h"
#include "macro/mesh/MeshCommands.h"

namespace c2d {

using namespace meshspec;

namespace {

void applyRigid(MeshContext& ctx, const MeshCommand& cmd) {
  for (const Record& r : cmd.data) {
    ctx.maxFields(r, 3, "e offset1 offset2");
    const int e = ctx.elementNumber(r, 0);
    const std::array<double, 2> o{ctx.number(r, 1), ctx.number(r, 2)};
    for (int a = 0; a < 2; ++a)
      if (!(o[a] >= 0))
        failAt(r, 1 + a, "a rigid end zone must not be negative",
               "give the length (m) from the node to the face where the flexible member begins");
    for (const auto& p : ctx.rigidEnds)
      if (p.element == e)
        failAt(r, 0,
               "element " + std::to_string(e) + " has rigid end zones already (line " +
                   std::to_string(p.origin.loc.line) + ")");
    ctx.rigidEnds.push_back({e, o, r});
  }
}

// The DeckError for a RIGId record whose element is not one this mesh input builds.
[[noreturn]] void notBuilt(const MeshContext& ctx, const MeshContext::PendingRigid& p) {
  const Model& model = ctx.model;
  const int e = p.element - 1;
  const std::string name = "element " + std::to_string(p.element);
  if (e < model.numElements() && !model.hasElement(e))
    failAt(p.origin, 0, name + " was removed (BLASt or REMOve): it cannot get rigid end zones");
  if (e < model.numElements())
    failAt(p.origin, 0,
           name + " was built by an earlier mesh input and carries its state: rigid end zones "
                  "are given with the element's definition",
           "give RIGId in the mesh input that defines the element");
  failAt(p.origin, 0, name + " is not defined", "define it with ELEMents or BLOCk");
}

}  // namespace

void applyRigidEnds(MeshContext& ctx) {
  Model& model = ctx.model;
  for (const auto& p : ctx.rigidEnds) {
    const auto it = ctx.elements.find(p.element);
    if (it == ctx.elements.end()) notBuilt(ctx, p);
    const MaterialSet& mat = *model.material(it->second.material);
    const std::array<int, 2> nodes{it->second.nodes[0] - 1, it->second.nodes[1] - 1};
    const Vec2 x1 = model.coord(nodes[0]), x2 = model.coord(nodes[1]);
    try {
      model.setElement(p.element - 1, makeElement(mat, nodes, x1, x2, p.offsets));
    } catch (const std::invalid_argument& err) {
      failAt(p.origin, 1, "element " + std::to_string(p.element) + ": " + err.what(),
             "offset1 + offset2 must be less than the distance between its nodes");
    }
    if (auto* os = ctx.out()) {
      *os << "      Rigid end zones: element " << p.element << ", ";
      num(*os, p.offsets[0]) << " at node " << it->second.nodes[0] << ", ";
      num(*os, p.offsets[1]) << " at node " << it->second.nodes[1] << ", flexible length ";
      num(*os, (x2 - x1).norm() - p.offsets[0] - p.offsets[1]) << "\n";
    }
  }
}

std::vector<MeshCommandEntry> rigidCommandTable() {
  std::vector<MeshCommandEntry> t;
  t.push_back(
      {meshSpec("RIGId",
                "Rigid end zones of frame elements: offset1 and offset2 (m) from the element's "
                "first and second node, along its axis, to the faces where the flexible member "
                "begins (a beam framing into a wall's or a column's face). The element's "
                "stiffness and strength are those of the flexible length between the faces "
                "(its end moments, where end hinges are checked, are the faces'); the nodes "
                "drive the faces through rigid arms (exact rotation under FINIte kinematics). "
                "Mass and self-weight stay those of the full length. Hinge laws (SOFTening, "
                "SECTion): a hinge at an end forms at the face, and the joint it becomes is "
                "there: the rigid zone turns with the node, the flexible part's end section "
                "with the node plus the joint's rotation. The log echoes each element's "
                "flexible length.",
                {}, "e offset1 offset2",
                {expr("e", "element number"), expr("offset1", "rigid zone at the first node (m)"),
                 expr("offset2", "rigid zone at the second node (m)")}),
       applyRigid});
  return t;
}

}  // namespace c2d
