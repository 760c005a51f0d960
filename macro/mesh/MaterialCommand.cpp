// The mesh command MATErial: a material set's sub-records (FRAMe, ELAStic,
// CROSs, RESUltant, DENSity, MASS, SHEAr, SMALl/FINIte, DAMPing, the laws of
// macro/mesh/SectionRecords), bound and echoed.
#include "macro/mesh/MeshCommands.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <set>
#include <sstream>

#include "macro/mesh/MaterialRecords.h"
#include "macro/mesh/SectionRecords.h"
#include "macro/mesh/SectionUnits.h"
#include "macro/mesh/SubRecordFields.h"
#include "macro/deck/Limits.h"

namespace c2d {

using namespace meshspec;

namespace {

// ---------------------------------------------------------------------------
// MATErial,m [label]: type record FRAMe, then sub-records until the blank.
// Sub-records take two text fields, then numbers.

void echoMaterial(std::ostream& os, const MaterialSet& m) {
  title(os, "M a t e r i a l   S e t   " + std::to_string(m.number) +
                (m.label.empty() ? "" : "   (" + m.label + ")"));
  os << "      Element type       " << m.elementType << "\n";
  os << "      Kinematics         " << (m.kinematics == Kinematics::Small ? "small" : "finite")
     << "\n";
  os << "      Shear deformation  " << (m.shear ? "on (Timoshenko)" : "off (Euler-Bernoulli)")
     << "\n";
  auto line = [&](const char* name, double v) {
    os << "      " << std::left << std::setw(19) << name << std::right;
    num(os, v) << "\n";
  };
  if (m.resEI) {
    line("EA (resultant)", *m.resEA);
    line("GA (resultant)", *m.resGA);
    line("EI (resultant)", *m.resEI);
  } else {
    line("Modulus E", m.E);
    line("Poisson ratio", m.nu);
  }
  if (m.A > 0 || !m.resEI) {
    line("Area A", m.A);
    line("Inertia I", m.I);
    line("Shear factor", m.kappa);
  }
  line("Density", m.density);
  if (m.contactRadius > 0) line("Contact radius", m.contactRadius);
  os << "      Mass               " << (m.mass == MassType::Lumped ? "lumped" : "consistent")
     << "\n";
  if (m.dampingA1 > 0) line("Damping a1 (s)", m.dampingA1);
  echoLaws(os, m);
}

// What one MATErial set has read so far: the set, its laws, and the records
// the checks across records point at.
struct MaterialReading {
  MaterialSet mat;
  LawRecords laws;
  const Record* elastic = nullptr;
  const Record* section = nullptr;
  const Record* resultant = nullptr;
  const Record* density = nullptr;
  const Record* kinematics = nullptr;
};

// The element type record, first in the data: FRAMe.
void readElementType(MeshContext& ctx, const MeshCommand& cmd, const CommandRegistry& subs,
                     int m) {
  const Record& h = cmd.head;
  if (cmd.data.empty())
    failAt(h, 0, "MATErial," + std::to_string(m) + " has no element type record",
           "the record after MATErial is the element type, FRAMe");
  const Record& type = cmd.data[0];
  if (!type.is("FRAMe")) {
    const CommandSpec* s = subs.find(type[0].text);
    if (s) failAt(type, 0, "the element type record (FRAMe) must come first in MATErial data");
    std::string hint = subs.suggest(type[0].text);
    failAt(type, 0, "unknown element type '" + type[0].text + "'",
           hint.empty() ? "the element type is FRAMe" : hint);
  }
  ctx.maxFields(type, 1, "FRAMe");
}

// The spec of a material record after the element type; a second FRAMe or an
// unknown name is an error.
const CommandSpec& materialRecordSpec(const CommandRegistry& subs, const Record& r) {
  const CommandSpec* s = subs.find(r[0].text);
  if (!s || s->key() == "fram") {
    if (s) failAt(r, 0, "element type given twice in one MATErial set");
    std::string hint = subs.suggest(r[0].text);
    failAt(r, 0, "unknown material record '" + r[0].text + "'",
           hint.empty() ? "see collapse2d --help for the material records" : hint);
  }
  return *s;
}

// The second field of r as one of the allowed options.
std::string recordOption(const MeshContext& ctx, const Record& r, const CommandSpec& s,
                         const std::string& syntax, std::initializer_list<const char*> allowed) {
  const std::string text2 = r.text(1);
  ctx.maxFields(r, 2, syntax);
  for (const char* a : allowed)
    if (keywordMatches(text2, a)) return std::string(a);
  failAt(r, 1, "unknown option '" + text2 + "' of " + s.name, "write " + syntax);
}

// ELAStic ISOTropic E nu.
void readElastic(const MeshContext& ctx, const Record& r, const CommandSpec& s,
                 MaterialReading& got) {
  const std::string syntax = "ELAStic ISOTropic E nu";
  const std::string text2 = r.text(1);
  subrecord::requireText(r, s.name, syntax);
  if (!text2.empty() && !keywordMatches(text2, "ISOTropic"))
    failAt(r, 1, "only isotropic elasticity is available for frames", "write " + syntax);
  const auto v = subrecord::values(ctx, r, s.name, 2, 1, syntax);
  if (v[0] <= 0) failAt(r, 2, "modulus E must be positive");
  if (v[1] <= -1 || v[1] >= 0.5) failAt(r, 3, "Poisson ratio must lie in (-1, 0.5)");
  got.mat.E = v[0];
  got.mat.nu = v[1];
  got.elastic = &r;
}

// CROSs SECTion: FEAPpv's frame record, A Ixx Iyy Ixy J kappa_1 kappa_2. A plane
// frame bends about one axis: it uses A, I = Ixx and the shear factor kappa_1
// (0: 5/6).
void readCrossSection(const MeshContext& ctx, const Record& r, const CommandSpec& s,
                      MaterialReading& got) {
  const std::string syntax = "CROSs SECTion A I [Iyy Ixy J kappa kappa2]";
  subrecord::requireText(r, s.name, "CROSs SECTion A I (or CROSs,,A,I)");
  const auto v = subrecord::values(ctx, r, s.name, 7, 2, syntax);
  if (v[0] <= 0) failAt(r, 2, "section area A must be positive");
  if (v[1] <= 0) failAt(r, 3, "section inertia I must be positive");
  if (v[5] < 0) failAt(r, 7, "shear factor must be positive");
  got.mat.A = v[0];
  got.mat.I = v[1];
  got.mat.kappa = v[5] != 0 ? v[5] : 5.0 / 6.0;
  got.section = &r;
}

// The numbers of a record NAME,,v1 ...: no option in its second field, one
// value at least, at most maxCount.
std::vector<double> valuesWithoutOption(const MeshContext& ctx, const Record& r,
                                        const CommandSpec& s, const std::string& syntax,
                                        std::size_t maxCount) {
  subrecord::requireText(r, s.name, syntax);
  if (!r.text(1).empty()) failAt(r, 1, s.name + " takes no option", "write " + syntax);
  return subrecord::values(ctx, r, s.name, maxCount, 1, syntax);
}

// DENSity,,rho [rotary inertia factor 1].
void readDensity(const MeshContext& ctx, const Record& r, const CommandSpec& s,
                 MaterialReading& got) {
  const auto v = valuesWithoutOption(ctx, r, s, "DENSity,,rho", 2);
  if (v[0] < 0) failAt(r, 2, "density must not be negative");
  if (v[1] != 0 && v[1] != 1) failAt(r, 3, "a rotary inertia factor other than 1 is not available");
  got.mat.density = v[0];
  got.density = &r;
}

// RADIus,,r: the contact radius in place of the section's.
void readRadius(const MeshContext& ctx, const Record& r, const CommandSpec& s,
                MaterialReading& got) {
  const auto v = valuesWithoutOption(ctx, r, s, "RADIus,,r", 1);
  if (!(v[0] > 0)) failAt(r, 2, "the contact radius must be positive");
  got.mat.contactRadius = v[0];
}

// RESUltant STIFfness EA GA EI.
void readResultant(const MeshContext& ctx, const Record& r, const CommandSpec& s,
                   MaterialReading& got) {
  const std::string syntax = "RESUltant STIFfness EA GA EI";
  subrecord::requireText(r, s.name, syntax);
  if (!keywordMatches(r.text(1), "STIFfness")) failAt(r, 1, "expected STIFfness", "write " + syntax);
  const auto v = subrecord::values(ctx, r, s.name, 3, 3, syntax);
  if (v[0] <= 0) failAt(r, 2, "EA must be positive");
  if (v[1] < 0) failAt(r, 3, "GA must not be negative");
  if (v[2] <= 0) failAt(r, 4, "EI must be positive");
  got.mat.resEA = v[0];
  got.mat.resGA = v[1];
  got.mat.resEI = v[2];
  got.resultant = &r;
}

// One material record after the element type, by its key.
void readMaterialRecord(MeshContext& ctx, const Record& r, const CommandSpec& s,
                        MaterialReading& got) {
  const std::string key = s.key();
  if (key == "elas") {
    readElastic(ctx, r, s, got);
  } else if (key == "cros") {
    readCrossSection(ctx, r, s, got);
  } else if (key == "shea") {
    if (r.text(1).empty()) {
      got.mat.shear = true;
    } else {
      got.mat.shear = recordOption(ctx, r, s, "SHEAr ON / SHEAr OFF", {"ON", "OFF"}) == "ON";
    }
  } else if (key == "smal" || key == "fini") {
    ctx.maxFields(r, 1, s.name);
    got.mat.kinematics = key == "smal" ? Kinematics::Small : Kinematics::Finite;
    got.kinematics = &r;
  } else if (key == "dens") {
    readDensity(ctx, r, s, got);
  } else if (key == "radi") {
    readRadius(ctx, r, s, got);
  } else if (key == "damp") {
    got.mat.dampingA1 = readDamping(ctx, r);
  } else if (key == "mass") {
    got.mat.mass = recordOption(ctx, r, s, "MASS LUMPed / MASS CONSistent",
                                {"LUMPed", "CONSistent"}) == "LUMPed"
                       ? MassType::Lumped
                       : MassType::Consistent;
  } else if (key == "resu") {
    readResultant(ctx, r, s, got);
  } else {
    bindLawRecord(ctx, r, s, got.mat, got.laws);
  }
}

// The checks across records: a stiffness (ELAStic and CROSs, or RESUltant),
// GA with shear on, the area DENSity needs.
void checkMaterialComplete(const Record& h, int m, const MaterialReading& got) {
  const MaterialSet& mat = got.mat;
  if (!mat.resEI) {
    if (!got.elastic)
      failAt(h, 0, "material " + std::to_string(m) + " has no ELAStic record",
             "give ELAStic ISOTropic E nu and CROSs SECTion A I, or RESUltant STIFfness EA GA EI");
    if (!got.section)
      failAt(h, 0, "material " + std::to_string(m) + " has no CROSs record",
             "give CROSs SECTion A I");
  } else if (mat.shear && *mat.resGA <= 0) {
    failAt(h, 0, "material " + std::to_string(m) + " has GA = 0 with shear deformation on",
           "give GA, or SHEAr OFF for Euler-Bernoulli");
  }
  if (got.density && mat.density > 0 && mat.A <= 0)
    failAt(*got.density, 2, "DENSity needs the section area: give CROSs SECTion A I too");
}

// The set into the model; a set given again (MESH re-entry) is noted as changed,
// unless it has or gets a SECTion.
void storeMaterial(MeshContext& ctx, const Record& h, int m, const MaterialReading& got) {
  if (const MaterialSet* before = ctx.model.material(m)) {
    if (before->section || got.mat.section)
      failAt(h, 0, "material " + std::to_string(m) + " has or gets a SECTion: it cannot be given again",
             "an RC member's history belongs to its section");
    auto [it, added] = ctx.changedMaterials.try_emplace(m);
    if (added) it->second.before = before->kinematics;  // as the existing elements have it
    it->second.head = h;
    it->second.kinematics = got.kinematics ? *got.kinematics : Record{};
  }
  ctx.model.materials()[m] = got.mat;
}

void applyMaterial(MeshContext& ctx, const MeshCommand& cmd) {
  const Record& h = cmd.head;
  const int m = ctx.materialNumber(h, 1);
  MaterialReading got;
  got.mat.number = m;
  got.mat.label = h.restOfLine(2);

  CommandRegistry subs;
  registerMaterialSubRecords(subs);
  readElementType(ctx, cmd, subs, m);
  got.mat.elementType = "FRAMe";
  for (std::size_t k = 1; k < cmd.data.size(); ++k) {
    const Record& r = cmd.data[k];
    readMaterialRecord(ctx, r, materialRecordSpec(subs, r), got);
  }

  finishLawRecords(h, got.laws, got.mat, got.elastic, got.section, got.resultant);
  warnSectionUnits(ctx, got.laws, got.mat);
  checkMaterialComplete(h, m, got);
  if (auto* os = ctx.out()) echoMaterial(*os, got.mat);
  storeMaterial(ctx, h, m, got);
}

}  // namespace

std::vector<MeshCommandEntry> materialCommandTable() {
  std::vector<MeshCommandEntry> t;
  t.push_back({meshSpec("MATErial",
                        "Material set m: the element type record (FRAMe), then material records "
                        "(see Material records) up to the blank record. Given again in a MESH "
                        "re-entry, the set's elements take the new data from the next step: their "
                        "section forces at the converged state and their history (plastic "
                        "curvature, hinge, initial strain, joint rotations) are kept and the new "
                        "stiffness acts on the increments; stiffness, SHEAr, density, MASS, "
                        "DAMPing, HARDening and SOFTening may change. Refused: SMALl <-> FINIte "
                        "(use HINGe2joint), HARDening/SOFTening for elastic SMALl elements, "
                        "removing the SOFTening of an active hinge, a Mu or yield moment below "
                        "the element's moment, capacity given back to a failed hinge.",
                        {expr("m", "material set number"), text("label", "free text")},
                        "FRAMe, then material records", {}),
               applyMaterial});
  return t;
}

}  // namespace c2d
