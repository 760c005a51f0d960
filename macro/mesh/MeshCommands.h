#pragma once
// The mesh commands (deck language sections 4 and 5): their specs and the
// functions that apply them to a Model, following FEAP's generation rules.
// Node, element and material numbers are 1-based in the deck, 0-based in Model.
#include <array>
#include <functional>
#include <iosfwd>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "core/Model.h"
#include "core/State.h"
#include "macro/deck/CommandSpec.h"
#include "macro/deck/Deck.h"
#include "macro/deck/Parameters.h"
#include "macro/deck/Warnings.h"

namespace c2d {

// Building blocks of the mesh commands' specs (MeshCommands, LoadCommands).
namespace meshspec {
// The DeckError at field i of record r.
[[noreturn]] void failAt(const Record& r, std::size_t i, const std::string& msg,
                         const std::string& hint = {});
FieldSpec expr(std::string name, std::string doc, std::string dflt = {});
FieldSpec text(std::string name, std::string doc, std::string dflt = {});
CommandSpec meshSpec(std::string name, std::string doc, std::vector<FieldSpec> fields,
                     std::string dataSyntax = {}, std::vector<FieldSpec> dataFields = {});
CommandSpec subSpec(std::string name, std::string doc, std::vector<FieldSpec> fields);
// The echo of the mesh data in FEAP's style: a spaced-out title, then columns
// of numbers.
void title(std::ostream& os, const std::string& t);
std::ostream& num(std::ostream& os, double v);
inline constexpr const char* kDofName[kNodeDofs] = {"u", "v", "theta"};
// Edge and coordinate commands: ADD (add values / set nonzero codes) or SET (replace).
enum class Mode { Add, Set };
Mode readMode(const Record& head, Mode dflt);
}  // namespace meshspec

// State of one mesh input, shared by the appliers. Values are evaluated when
// their record is applied (a later PARAmeter block cannot change them), even
// for the parts FEAP applies at the end of the mesh input (elements, edge and
// coordinate commands, joints).
struct MeshContext {
  MeshContext(Model& m, Parameters& p, std::ostream* e)
      : model(m), params(p), echo(e), elementsBefore(m.numElements()) {}

  Model& model;
  Parameters& params;
  std::ostream* echo;  // mesh echo, null for none
  // The element slots the model had before this mesh input (a MESH re-entry):
  // the mesh input that made them had no gaps, so an empty one was removed
  // (BLASt, REMOve) and stays empty.
  int elementsBefore = 0;
  bool print = true;   // PRINt / NOPRint

  // Limits from the control record; 0: count them (the model grows as needed).
  int maxNodes = 0, maxElements = 0, maxMaterials = 0;

  struct PendingElement {
    int material = 0;
    std::array<int, 2> nodes{};  // deck numbers
    // The record that gave (or generated) it: a BLOCk of a million elements
    // shares one (a copy each took 0.8 kB per element).
    const Record* origin = nullptr;
    bool generated = false;
  };
  std::map<int, PendingElement> elements;  // by deck element number

  struct PendingJoint {
    int master = 0, slave = 0;  // deck numbers
    Record origin;
  };
  std::vector<PendingJoint> joints;

  // Parts built on the members once the elements are (INFIll's struts), in
  // deck order, before the deferred commands (which may name their elements).
  std::vector<std::function<void(MeshContext&)>> afterElements;
  // RIGId: rigid end zones, given to their elements once those are built.
  struct PendingRigid {
    int element = 0;  // deck number
    std::array<double, 2> offsets{};
    Record origin;
  };
  std::vector<PendingRigid> rigidEnds;

  // Edge and coordinate commands, run in deck order once the mesh is complete.
  std::vector<std::function<void(MeshContext&)>> deferred;
  // Elements weakened (WEAKen; deck numbers) and the line of the record.
  std::map<int, int> weakened;
  // Nodes given loads or boundary codes: they must get coordinates.
  std::map<int, Record> referencedNodes;

  // Proportional load tables above 1 named by FPROportional: the first record
  // and field naming each (PROP must define them).
  std::map<int, std::pair<Record, std::size_t>> tableRefs;

  // The record that gave each node its coordinates (deck number - 1; the records
  // outlive the context), for messages about nodes.
  std::vector<const Record*> coordOrigin;
  void setCoordOrigin(int n, const Record& r);
  // The GROUnd and MEMBers records of CONTact, the GRAVity and SITE records,
  // blank when not given.
  Record groundOrigin, membersOrigin, gravityOrigin, siteOrigin;
  Warnings* warnings = nullptr;  // null: warnings are dropped
  // The SECTion, STIRrups and SOFTening records of each material set (blank:
  // none), for the checks against its members' lengths (macro/mesh/SectionUnits).
  struct LawOrigin {
    Record section, stirrups, softening;
  };
  std::map<int, LawOrigin> lawOrigins;
  // Checks that need the initial mesh, run by its binder before computing
  // (set by the commands that need them; may be empty).
  std::function<void(const MeshContext&)> meshChecks;
  // Called with the model once every node has its coordinates, before the
  // elements are built from them (an ensemble's node jitter); may be empty.
  std::function<void(Model&)> beforeElements;
  // SHIFt: the origin of POLAr; the nodes POLAr converted (each only once, as FEAP).
  Vec2 polarOrigin = Vec2::Zero();
  std::map<int, int> polarConverted;  // node -> line of the POLAr record

  int highestNode = 0, highestElement = 0, lastBlockMaterial = 0;
  bool topologyChanged = false;

  // MATErial given again for a set that exists: the new data go to the set's
  // existing elements when the mesh input is complete (elements/MaterialUpdate).
  struct MaterialChangeSource {
    Kinematics before = Kinematics::Small;
    Record head;        // MATErial,m
    Record kinematics;  // its SMALl/FINIte record (blank: none given)
  };
  std::map<int, MaterialChangeSource> changedMaterials;
  // The analysis state of a MESH re-entry (committed displacements); null: a
  // model not yet analysed.
  const State* state = nullptr;

  std::ostream* out() const { return print ? echo : nullptr; }

  // Value of field i (0 when absent or empty).
  double number(const Record& r, std::size_t i) const;
  int integer(const Record& r, std::size_t i, std::string_view what) const;
  // A node number in field i: positive, within numnp; grows the model when counting.
  int node(const Record& r, std::size_t i, std::string_view what = "node number");
  // Node n must exist (grows the model when counting): positive, within numnp
  // and within DeckLimits; field i of r locates the error.
  void ensureNode(long long n, const Record& r, std::size_t i);
  // withinNumel: refuse a number beyond numel (false: a number that may name a
  // part numbered after the deck's elements, an INFIll strut; checked when the
  // mesh is complete).
  int elementNumber(const Record& r, std::size_t i, bool withinNumel = true);
  int materialNumber(const Record& r, std::size_t i);
  // The stepped element range "n1 n2 inc" in fields i, i+1, i+2 (n2 empty:
  // n1; inc empty: 1), checked (withinNumel: as elementNumber's).
  struct ElementRange {
    int n1 = 0, n2 = 0, inc = 1;
  };
  ElementRange elementRange(const Record& r, std::size_t i, bool withinNumel = true);
  // DeckError when the record has more than max fields.
  void maxFields(const Record& r, std::size_t max, std::string_view syntax) const;
};

using MeshApplier = void (*)(MeshContext&, const MeshCommand&);

struct MeshCommandEntry {
  CommandSpec spec;
  MeshApplier apply = nullptr;  // null: handled by the parser (END, PARAmeter, INCLude)
};

// The mesh commands, in the order --help lists them.
std::vector<MeshCommandEntry> meshCommandTable();
// The families' entries (one file each), in the order meshCommandTable lists them.
std::vector<MeshCommandEntry> geometryCommandTable();  // COORdinates ELEMents BLOCk JOINt SHIFt POLAr
std::vector<MeshCommandEntry> materialCommandTable();  // MATErial
std::vector<MeshCommandEntry> nodalCommandTable();     // BOUNdary FORCe DISPlacement FPROportional E... C...
std::vector<MeshCommandEntry> contactCommandTable();   // CONTact
std::vector<MeshCommandEntry> infillCommandTable();    // INFIll
std::vector<MeshCommandEntry> weakenCommandTable();    // WEAKen
std::vector<MeshCommandEntry> rigidCommandTable();     // RIGId
// RIGId's records applied to the elements just built (finishMesh).
void applyRigidEnds(MeshContext& ctx);
void registerMeshCommands(CommandRegistry& registry);
// Element types (FRAMe) and material sub-records (ELAStic, CROSs, ...).
void registerMaterialSubRecords(CommandRegistry& registry);

// End of a mesh input: build the elements, run the deferred commands, add the
// joints and check that nothing is left undefined; where locates the errors
// that belong to no single record.
void finishMesh(MeshContext& ctx, const SourceLoc& where, const std::string& whereText);

// The DeckError for a MATErial record given again (r: its SMALl/FINIte record,
// or the MATErial record) that would change the kinematics of set m, whose
// elements have `before`.
[[noreturn]] void refuseKinematicsChange(const Record& r, int m, Kinematics before);

}  // namespace c2d
