#include "macro/run/MeshReentry.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

#include "elements/Joints.h"
#include "macro/mesh/MeshCommands.h"
#include "macro/deck/DeckParser.h"
#include "macro/mesh/ParseDeck.h"
#include "macro/deck/DeckReader.h"
#include "macro/mesh/MeshBinder.h"

namespace c2d {

namespace {

// What a MESH re-entry may not change in a material set with elements.
struct MaterialShape {
  Kinematics kinematics = Kinematics::Small;
  bool elastic = false;  // SMALl without HARDening/SOFTening: elastic frame elements
};

}  // namespace

std::vector<MeshItem> meshReentryItems(const Macro& m) {
  std::vector<Record> records;
  if (!m.optionText.empty()) {
    const std::filesystem::path base = std::filesystem::path(m.record.loc.file).parent_path();
    const std::filesystem::path file = base / m.optionText;
    if (!std::filesystem::exists(file))
      throw DeckError(m.record.fieldLoc(1), "MESH: no file '" + file.string() + "'",
                      m.record.excerpt(m.record.fieldLoc(1)));
    records = DeckReader::readFile(file.string());
  } else {
    records = m.data;
  }
  return parseMeshRecords(std::move(records), m.record.loc.file);
}

namespace {

// MATErial records of MESH re-entries, in deck order, that would change the
// kinematics of a set whose elements exist, or give HARDening/SOFTening to its
// elastic frame elements (before HINGe2joint, which makes them elastic Reissner
// beams that ignore the laws): refused before any computing (the re-entry checks
// again when it is applied). A re-entry that builds elements is left to that check.
void checkMaterialChanges(const std::vector<Macro>& list, std::map<int, MaterialShape>& sets,
                          const std::set<int>& used, const Parameters& params, bool& collapse) {
  for (const Macro& m : list) {
    checkMaterialChanges(m.body, sets, used, params, collapse);
    if (m.is("hing")) collapse = true;
    if (!m.is("mesh")) continue;
    const std::vector<MeshItem> items = meshReentryItems(m);
    bool builds = false;
    for (const MeshItem& item : items)
      if (const auto* c = std::get_if<MeshCommand>(&item))
        builds = builds || c->head.is("ELEMents") || c->head.is("BLOCk");
    if (builds) continue;
    for (const MeshItem& item : items) {
      const auto* c = std::get_if<MeshCommand>(&item);
      if (!c || !c->head.is("MATErial") || c->head.size() < 2) continue;
      int number = 0;
      try {
        number = Expression::parse(c->head[1]).evalInt(params, "material number");
      } catch (const DeckError&) {
        continue;  // a parameter set later: checked when the re-entry is applied
      }
      Kinematics kin = Kinematics::Small;
      const Record* where = &c->head;
      const Record* law = nullptr;
      for (const Record& r : c->data) {
        if (r.is("SMALl") || r.is("FINIte")) {
          kin = r.is("SMALl") ? Kinematics::Small : Kinematics::Finite;
          where = &r;
        }
        if (!law && (r.is("HARDening") || r.is("SOFTening"))) law = &r;
      }
      auto it = sets.find(number);
      if (it != sets.end() && used.count(number)) {
        if (it->second.kinematics != kin)
          refuseKinematicsChange(*where, number, it->second.kinematics);
        if (it->second.elastic && law && !collapse)
          throw DeckError(law->fieldLoc(0),
                          "material " + std::to_string(number) +
                              " has elastic frame elements (built without HARDening and "
                              "SOFTening): the laws cannot be added in a MESH re-entry",
                          law->excerpt(law->fieldLoc(0).col),
                          "give the laws in the mesh input, where the elements are built");
        continue;  // the elements keep their class
      }
      sets[number] = {kin, kin == Kinematics::Small && !law};
    }
  }
}

// The MESH re-entries of the BATCh blocks applied in deck order to a model
// built again from the mesh input, with the parameters the bind pass ends
// with: their deck errors (an unknown record, an undefined parameter, a
// negative mu) are found before the first step. What depends on the run
// before the re-entry (the nodes' positions against a new ground) is left to
// the re-entry itself.
void applyReentries(const std::vector<Macro>& list, Model& model, Parameters& params) {
  for (const Macro& m : list) {
    applyReentries(m.body, model, params);
    if (!m.is("mesh")) continue;
    try {
      applyMesh(meshReentryItems(m), params, model, nullptr, nullptr, nullptr);
    } catch (const AnalysisError&) {
      // The ground against the nodes as the run will have moved them: at the re-entry.
    }
  }
}

bool hasReentry(const std::vector<Macro>& list) {
  return std::any_of(list.begin(), list.end(),
                     [](const Macro& m) { return m.is("mesh") || hasReentry(m.body); });
}

// The re-entries applied to the mesh input built again.
void applyAllReentries(const Problem& problem, const Parameters& start, const Parameters& bound,
                       const std::vector<std::vector<Macro>>& batches) {
  if (std::none_of(batches.begin(), batches.end(), [](const auto& b) { return hasReentry(b); }))
    return;
  Parameters params = start;
  Model model = buildModel(problem, params, nullptr, nullptr);
  params = bound;
  for (const auto& batch : batches) applyReentries(batch, model, params);
}

}  // namespace

void checkMeshReentries(const Problem& problem, const Model& model, const Parameters& start,
                        const Parameters& bound, const std::vector<std::vector<Macro>>& batches) {
  std::map<int, MaterialShape> sets;
  for (const auto& [number, mat] : model.materials())
    sets[number] = {mat.kinematics,
                    mat.kinematics == Kinematics::Small && !mat.hardening && !mat.softening};
  std::set<int> used;
  for (const auto& e : model.elements())
    if (e) used.insert(e->materialNumber());
  bool collapse = false;
  for (const auto& batch : batches) checkMaterialChanges(batch, sets, used, bound, collapse);
  applyAllReentries(problem, start, bound, batches);
}

void applyMeshReentry(const std::vector<MeshItem>& items, Parameters& params, Model& model,
                      Analysis& analysis, std::ostream& log) {
  applyMesh(items, params, model, &log, nullptr, &analysis.state());
  installJoints(model);
  model.bumpTopology();
  analysis.topologyChanged();
  log << "  MESH   re-entered: " << model.numNodes() << " nodes, " << model.numElements()
      << " elements, " << analysis.assembler().dofs().numEquations() << " equations\n";
}

}  // namespace c2d
