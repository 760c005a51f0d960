// The mesh commands' table (every family's: GeometryCommands,
// MaterialCommand, NodalCommands, ContactCommand, LoadCommands, BlastCommand;
// PRINt, NOPRint and what the parser handles: PARAmeter, INCLude, END) and the
// end of a mesh input (finishMesh: elements built, joints, edge and point
// data, the checks of the whole mesh).
#include "macro/mesh/MeshCommands.h"

#include <algorithm>
#include <iomanip>
#include <ostream>
#include <set>

#include "elements/ElementFactory.h"
#include "elements/Joints.h"
#include "elements/MaterialUpdate.h"
#include "macro/mesh/BlastCommand.h"
#include "macro/mesh/LoadCommands.h"
#include "macro/deck/Limits.h"

namespace c2d {

using namespace meshspec;

namespace {

void applyPrint(MeshContext& ctx, const MeshCommand&) { ctx.print = true; }
void applyNoPrint(MeshContext& ctx, const MeshCommand&) { ctx.print = false; }

}  // namespace

std::vector<MeshCommandEntry> meshCommandTable() {
  std::vector<MeshCommandEntry> t;
  for (auto family : {geometryCommandTable, materialCommandTable, nodalCommandTable,
                      contactCommandTable, loadCommandTable, blastCommandTable,
                      infillCommandTable, weakenCommandTable, rigidCommandTable})
    for (auto& e : family()) t.push_back(std::move(e));
  t.push_back({meshSpec("PRINt", "Echo the mesh data in the log (default).", {}), applyPrint});
  t.push_back({meshSpec("NOPRint", "Stop echoing the mesh data in the log.", {}), applyNoPrint});
  CommandSpec para = meshSpec("PARAmeter",
                              "Parameter block: records 'name = expression' up to the blank "
                              "record; names of any length, case-insensitive.",
                              {}, "name = expression",
                              {text("name", "parameter name"), expr("expression", "its value")});
  para.aliases = {"CONStant"};
  t.push_back({para, nullptr});
  t.push_back({meshSpec("INCLude", "Read another file here (relative to this file).",
                        {text("file", "file name")}),
               nullptr});
  t.push_back({meshSpec("END", "End of the mesh input.", {}), nullptr});
  return t;
}

void registerMeshCommands(CommandRegistry& registry) {
  for (auto& e : meshCommandTable()) registry.add(std::move(e.spec));
}

// ---------------------------------------------------------------------------
// end of the mesh input

void refuseKinematicsChange(const Record& r, int m, Kinematics before) {
  const std::string was = before == Kinematics::Small ? "SMALl" : "FINIte";
  failAt(r, 0,
         "material " + std::to_string(m) + " has elements with " + was +
             " kinematics: the kinematics of a material set cannot change in a MESH re-entry",
         "keep " + was +
             "; HINGe2joint switches the elements to finite kinematics with their "
             "state");
}

namespace {

// The elements the input defined, checked (material, nodes, length) and built.
void buildElements(MeshContext& ctx) {
  Model& model = ctx.model;
  for (const auto& [num, pe] : ctx.elements) {
    const Record& r = *pe.origin;
    const std::string what =
        "element " + std::to_string(num) + (pe.generated ? " (generated from this record)" : "");
    const std::size_t matField = r.is("CARTesian") ? 5 : 2;
    const MaterialSet* mat = model.material(pe.material);
    if (!mat)
      failAt(r, matField,
             what + " uses material " + std::to_string(pe.material) + ", which is not defined",
             "define it with MATErial," + std::to_string(pe.material));
    for (int a = 0; a < 2; ++a) {
      const int n = pe.nodes[a];
      if (n < 1 || n > model.numNodes() || !model.hasCoord(n - 1))
        failAt(r, r.is("CARTesian") ? 3 : 3 + a,
               what + " uses node " + std::to_string(n) + ", which has no coordinates");
    }
    if (pe.nodes[0] == pe.nodes[1])
      failAt(r, 3, what + " connects node " + std::to_string(pe.nodes[0]) + " to itself");
    const Vec2& x1 = model.coord(pe.nodes[0] - 1);
    const Vec2& x2 = model.coord(pe.nodes[1] - 1);
    if ((x2 - x1).norm() == 0) failAt(r, 3, what + " has zero length");
    model.setElement(num - 1, makeElement(*mat, {pe.nodes[0] - 1, pe.nodes[1] - 1}, x1, x2));
  }
}

// MATErial given again: its existing elements (not rebuilt by this input) take
// the new data with their state. A change of kinematics is refused at the
// record; an element that cannot take the data ends the analysis at the record.
void applyChangedMaterials(MeshContext& ctx) {
  Model& model = ctx.model;
  std::vector<int> rebuilt;
  for (const auto& [num, pe] : ctx.elements) rebuilt.push_back(num - 1);
  const State none;
  for (const auto& [m, src] : ctx.changedMaterials) {
    const MaterialSet& mat = *model.material(m);
    bool used = false;
    for (int e = 0; e < model.numElements() && !used; ++e)
      used = model.elements()[e] && model.element(e).materialNumber() == m &&
             std::find(rebuilt.begin(), rebuilt.end(), e) == rebuilt.end();
    if (!used) continue;
    if (mat.kinematics != src.before)
      refuseKinematicsChange(src.kinematics.blank() ? src.head : src.kinematics, m, src.before);
    const Status st = changeMaterial(model, ctx.state ? *ctx.state : none, mat, rebuilt);
    if (!st)
      throw AnalysisError(src.head.fieldLoc(0).str() + ": error: MATErial," + std::to_string(m) +
                          " given again: " + st.why);
    if (auto* os = ctx.out())
      *os << "      Material set " << m << " given again: its elements take the new data\n";
  }
}

// The edge and point data, applied now that every coordinate is known.
void applyDeferred(MeshContext& ctx) {
  if (auto* os = ctx.out(); os && !ctx.deferred.empty()) {
    title(*os, "E d g e   a n d   C o o r d i n a t e   V a l u e s");
    *os << "      Command           Node   (codes, forces or displacements: u, v, theta)\n";
  }
  for (auto& f : ctx.deferred) f(ctx);
}

// The JOINt records: nodes with coordinates, coincident, each slave once.
void addJoints(MeshContext& ctx) {
  Model& model = ctx.model;
  const double tol = 1e-3 * model.characteristicLength();
  for (const auto& j : ctx.joints) {
    for (int a = 0; a < 2; ++a) {
      const int n = a == 0 ? j.master : j.slave;
      if (!model.hasCoord(n - 1))
        failAt(j.origin, a, "joint node " + std::to_string(n) + " has no coordinates");
    }
    const double gap = (model.coord(j.master - 1) - model.coord(j.slave - 1)).norm();
    if (gap > tol) {
      std::ostringstream s;
      s << "joint nodes " << j.master << " and " << j.slave << " are not coincident (distance "
        << gap << ")";
      failAt(j.origin, 1, s.str());
    }
    for (const auto& existing : model.joints())
      if (existing.slave == j.slave - 1)
        failAt(j.origin, 1, "node " + std::to_string(j.slave) + " is already the slave of a joint");
    model.joints().push_back(Joint{j.master - 1, j.slave - 1, JointForm::Condensed});
    if (auto* os = ctx.out())
      *os << "      Joint: master node " << j.master << ", slave node " << j.slave << "\n";
  }
}

// Every element number from 1 to numel (or to the last one) defined.
void checkElementsDefined(const MeshContext& ctx, const SourceLoc& where,
                          const std::string& whereText) {
  const Model& model = ctx.model;
  const int expected = ctx.maxElements > 0 ? ctx.maxElements : model.numElements();
  for (int e = 0; e < expected; ++e)
    if (e >= model.numElements() || (!model.elements()[e] && e >= ctx.elementsBefore))
      throw DeckError(
          where,
          "element " + std::to_string(e + 1) + " is not defined" +
              (ctx.maxElements > 0 ? " (numel = " + std::to_string(ctx.maxElements) + ")" : ""),
          whereText,
          ctx.maxElements > 0 ? "define it, or set numel to 0 to have elements counted"
                              : "element numbers must run from 1 without gaps");
}

// A joint friction moment (SOFTening's Mr) acts on a joint condensed into its
// one slave element; on a joint shared by more it would be ignored.
void checkJointFriction(const MeshContext& ctx) {
  for (const auto& j : ctx.joints)
    if (const Joint joint{j.master - 1, j.slave - 1, JointForm::Condensed};
        jointFriction(ctx.model, joint.slave) > 0 && !condensable(ctx.model, joint))
      failAt(j.origin, 1,
             "the joint friction Mr of the materials at node " + std::to_string(j.slave) +
                 " needs a joint condensed into one element: the slave node has more than one "
                 "element, nodal data, or is the master of another joint",
             "give the slave node one element only, or leave Mr out");
}

// The input's gathered data, spent: a new topology version if it changed one.
void closeMeshInput(MeshContext& ctx) {
  if (ctx.topologyChanged) ctx.model.bumpTopology();
  ctx.elements.clear();
  ctx.changedMaterials.clear();
  ctx.afterElements.clear();
  ctx.weakened.clear();
  ctx.deferred.clear();
  ctx.joints.clear();
  ctx.rigidEnds.clear();
  ctx.referencedNodes.clear();
  ctx.topologyChanged = false;
}

}  // namespace

void finishMesh(MeshContext& ctx, const SourceLoc& where, const std::string& whereText) {
  Model& model = ctx.model;
  if (ctx.beforeElements) ctx.beforeElements(model);
  buildElements(ctx);
  applyRigidEnds(ctx);
  for (auto& f : ctx.afterElements) f(ctx);
  if (!ctx.changedMaterials.empty()) applyChangedMaterials(ctx);
  applyDeferred(ctx);
  for (const auto& [node, r] : ctx.referencedNodes)
    if (!model.hasCoord(node - 1))
      failAt(r, 0, "node " + std::to_string(node) + " has no coordinates");
  if (!ctx.joints.empty()) addJoints(ctx);
  checkElementsDefined(ctx, where, whereText);
  checkJointFriction(ctx);
  closeMeshInput(ctx);
}

}  // namespace c2d
