#pragma once
// MESH inside a BATCh block: a re-entry of mesh records (its data lines or a
// file) applied to the model between two solution commands. Its records, and
// the bind pass's checks of every re-entry of a problem before any computing.
#include <ostream>
#include <vector>

#include "core/Model.h"
#include "macro/deck/Deck.h"
#include "macro/deck/Macro.h"
#include "macro/mesh/MeshBinder.h"
#include "solvers/Analysis.h"

namespace c2d {

// The mesh records of a re-entry (MESH with data lines, or MESH,file).
// Throws DeckError (a file that does not exist, a record that is no mesh record).
std::vector<MeshItem> meshReentryItems(const Macro& m);

// The re-entries of the bound BATCh blocks (`batches`) checked before any
// computing: a MATErial record that would change the kinematics of a set whose
// elements exist (`model`: the mesh input as built), or give HARDening or
// SOFTening to its elastic frame elements before HINGe2joint; then every
// re-entry applied in deck order to the mesh input built again from the
// parameters at the start (`start`), with those the bind pass ends with
// (`bound`): their deck errors (an unknown record, an undefined parameter, a
// negative mu) are found before the first step. What depends on the run
// before the re-entry (the nodes' positions against a new ground) is left to
// the re-entry itself. Throws DeckError.
void checkMeshReentries(const Problem& problem, const Model& model, const Parameters& start,
                        const Parameters& bound, const std::vector<std::vector<Macro>>& batches);

// A re-entry's items applied to the model at the analysis's committed state
// (after the commit that ends the step before it): material sets given again
// take their data with their state, new joints are installed, the analysis
// takes the new topology; logged.
void applyMeshReentry(const std::vector<MeshItem>& items, Parameters& params, Model& model,
                      Analysis& analysis, std::ostream& log);

}  // namespace c2d
