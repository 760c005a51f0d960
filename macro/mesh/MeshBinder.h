#pragma once
// The third phase for the mesh: mesh items applied to a Model in deck order,
// with the parameter table (PARAmeter blocks inside the mesh update it as they
// come) and an optional mesh echo. Used for a problem's initial mesh and again
// for MESH re-entry on an existing model.
#include <array>
#include <functional>
#include <iosfwd>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/Model.h"
#include "macro/deck/CommandSpec.h"
#include "macro/deck/Deck.h"
#include "macro/mesh/MeshCommands.h"
#include "macro/deck/Parameters.h"
#include "macro/deck/Warnings.h"

namespace c2d {

// The control record: numnp numel nummat ndm ndf nen (zeros: counted from the mesh).
struct ControlData {
  int numnp = 0, numel = 0, nummat = 0;
  int ndm = 2, ndf = 3, nen = 2;
};

// What a problem's mesh input leaves for the checks made once its BATCh blocks
// are bound too, and where its warnings go.
struct MeshFacts {
  Warnings* warnings = nullptr;  // in (null: warnings are dropped)
  // out: the proportional load tables above 1 that FPROportional names, with the
  // record and field naming each first.
  std::map<int, std::pair<Record, std::size_t>> loadTables;
  // in: called once every node has its coordinates, before the elements are
  // built (MeshContext::beforeElements); may be empty.
  std::function<void(Model&)> beforeElements;
};

class MeshBinder {
 public:
  MeshBinder(Model& model, Parameters& params, std::ostream* echo, Warnings* warnings = nullptr);

  // Evaluates and checks the control record (ndm 2, ndf 3, nen 2 or 0) and sets
  // the node, element and material limits; nonzero numnp sizes the model.
  ControlData setControl(const Record& control);
  // FEAP's keyword form (Problem::controlKeywords), the same checks.
  ControlData setControl(const std::vector<Record>& keywords);
  // Applies the items in order. Elements, edge and coordinate commands and
  // joints wait for finish().
  void apply(const std::vector<MeshItem>& items);
  // End of the mesh input (the END record, for errors that belong to no record).
  void finish(const SourceLoc& where, const std::string& whereText = {});
  // Checks of a problem's initial mesh (after finish): no node inside the ground,
  // gravity only with densities (an error when no element has one, a warning for
  // the material sets without), a warning for nodes that no element uses.
  void checkInitialMesh();
  // Checks of a MESH re-entry that gave a GROUnd (before: the ground the model
  // had): a ground raised into the structure at its positions now (state; null:
  // at its coordinates) is refused, an AnalysisError at the GROUnd record, as in
  // the mesh input.
  void checkGroundReentry(const std::optional<Ground>& before, const State* state);
  const std::map<int, std::pair<Record, std::size_t>>& loadTableRefs() const {
    return ctx_.tableRefs;
  }

  const CommandRegistry& registry() const { return registry_; }
  // The analysis state a MESH re-entry starts from (material sets given again).
  void setState(const State* state) { ctx_.state = state; }
  void setBeforeElements(std::function<void(Model&)> f) { ctx_.beforeElements = std::move(f); }

 private:
  struct ControlField {
    const Record* record = nullptr;
    std::size_t field = 0;
  };
  ControlData applyControl(const std::array<int, 9>& values,
                           const std::array<ControlField, 9>& where, const std::string& hint);

  MeshContext ctx_;
  std::vector<MeshCommandEntry> table_;
  CommandRegistry registry_;
};

// A problem's model: control record, mesh items, END.
Model buildModel(const Problem& problem, Parameters& params, std::ostream* echo,
                 MeshFacts* facts = nullptr);

// Mesh items applied to an existing model (MESH re-entry), then finished: new
// ELEMents/BLOCk elements are built (replacing elements of the same number);
// existing elements are kept; those of a material set given again take its new
// data with their state (committed displacements from state; null: zero).
// end, when given, locates end-of-mesh errors.
void applyMesh(const std::vector<MeshItem>& items, Parameters& params, Model& model,
               std::ostream* echo, const Record* end = nullptr, const State* state = nullptr);

}  // namespace c2d
