#pragma once
// The third phase for the mesh: mesh items applied to a Model in deck order,
// with the parameter table (PARAmeter blocks inside the mesh update it as they
// come) and an optional mesh echo. Used for a problem's initial mesh and again
// for MESH re-entry on an existing model.
#include <iosfwd>
#include <vector>

#include "core/Model.h"
#include "macro/CommandSpec.h"
#include "macro/Deck.h"
#include "macro/MeshCommands.h"
#include "macro/Parameters.h"

namespace c2d {

// The control record: numnp numel nummat ndm ndf nen (zeros: counted from the mesh).
struct ControlData {
  int numnp = 0, numel = 0, nummat = 0;
  int ndm = 2, ndf = 3, nen = 2;
};

class MeshBinder {
 public:
  MeshBinder(Model& model, Parameters& params, std::ostream* echo);

  // Evaluates and checks the control record (ndm 2, ndf 3, nen 2 or 0) and sets
  // the node, element and material limits; nonzero numnp sizes the model.
  ControlData setControl(const Record& control);
  // Applies the items in order. Elements, edge and coordinate commands and
  // joints wait for finish().
  void apply(const std::vector<MeshItem>& items);
  // End of the mesh input (the END record, for errors that belong to no record).
  void finish(const SourceLoc& where, const std::string& whereText = {});

  const CommandRegistry& registry() const { return registry_; }
  // The analysis state a MESH re-entry starts from (material sets given again).
  void setState(const State* state) { ctx_.state = state; }

 private:
  MeshContext ctx_;
  std::vector<MeshCommandEntry> table_;
  CommandRegistry registry_;
};

// A problem's model: control record, mesh items, END.
Model buildModel(const Problem& problem, Parameters& params, std::ostream* echo);

// Mesh items applied to an existing model (MESH re-entry), then finished: new
// ELEMents/BLOCk elements are built (replacing elements of the same number);
// existing elements are kept; those of a material set given again take its new
// data with their state (committed displacements from state; null: zero).
// end, when given, locates end-of-mesh errors.
void applyMesh(const std::vector<MeshItem>& items, Parameters& params, Model& model,
               std::ostream* echo, const Record* end = nullptr, const State* state = nullptr);

}  // namespace c2d
