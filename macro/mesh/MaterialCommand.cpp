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
  os << "      Mass               " << (m.mass == MassType::Lumped ? "lumped" : "consistent")
     << "\n";
  if (m.dampingA1 > 0) line("Damping a1 (s)", m.dampingA1);
  echoLaws(os, m);
}

void applyMaterial(MeshContext& ctx, const MeshCommand& cmd) {
  const Record& h = cmd.head;
  const int m = ctx.materialNumber(h, 1);
  MaterialSet mat;
  mat.number = m;
  mat.label = h.restOfLine(2);

  CommandRegistry subs;
  registerMaterialSubRecords(subs);

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
  mat.elementType = "FRAMe";

  const Record *elasticRec = nullptr, *sectionRec = nullptr, *resultantRec = nullptr;
  LawRecords laws;
  const Record* densityRec = nullptr;
  const Record* kinematicsRec = nullptr;
  for (std::size_t k = 1; k < cmd.data.size(); ++k) {
    const Record& r = cmd.data[k];
    const CommandSpec* s = subs.find(r[0].text);
    if (!s || s->key() == "fram") {
      if (s) failAt(r, 0, "element type given twice in one MATErial set");
      std::string hint = subs.suggest(r[0].text);
      failAt(r, 0, "unknown material record '" + r[0].text + "'",
             hint.empty() ? "see collapse2d --help for the material records" : hint);
    }
    const std::string key = s->key();
    const std::string text2 = r.text(1);
    auto numericText = [&](const std::string& syntax) { subrecord::requireText(r, s->name, syntax); };
    auto values = [&](std::size_t maxCount, std::size_t required, const std::string& syntax) {
      return subrecord::values(ctx, r, s->name, maxCount, required, syntax);
    };
    auto option = [&](const std::string& syntax, std::initializer_list<const char*> allowed) {
      ctx.maxFields(r, 2, syntax);
      for (const char* a : allowed)
        if (keywordMatches(text2, a)) return std::string(a);
      failAt(r, 1, "unknown option '" + text2 + "' of " + s->name, "write " + syntax);
    };

    if (key == "elas") {
      const std::string syntax = "ELAStic ISOTropic E nu";
      numericText(syntax);
      if (!text2.empty() && !keywordMatches(text2, "ISOTropic"))
        failAt(r, 1, "only isotropic elasticity is available for frames", "write " + syntax);
      const auto v = values(2, 1, syntax);
      if (v[0] <= 0) failAt(r, 2, "modulus E must be positive");
      if (v[1] <= -1 || v[1] >= 0.5) failAt(r, 3, "Poisson ratio must lie in (-1, 0.5)");
      mat.E = v[0];
      mat.nu = v[1];
      elasticRec = &r;
    } else if (key == "cros") {
      // FEAPpv's frame record: A Ixx Iyy Ixy J kappa_1 kappa_2. A plane frame bends
      // about one axis: it uses A, I = Ixx and the shear factor kappa_1 (0: 5/6).
      const std::string syntax = "CROSs SECTion A I [Iyy Ixy J kappa kappa2]";
      numericText("CROSs SECTion A I (or CROSs,,A,I)");
      const auto v = values(7, 2, syntax);
      if (v[0] <= 0) failAt(r, 2, "section area A must be positive");
      if (v[1] <= 0) failAt(r, 3, "section inertia I must be positive");
      if (v[5] < 0) failAt(r, 7, "shear factor must be positive");
      mat.A = v[0];
      mat.I = v[1];
      mat.kappa = v[5] != 0 ? v[5] : 5.0 / 6.0;
      sectionRec = &r;
    } else if (key == "shea") {
      if (text2.empty()) {
        mat.shear = true;
      } else {
        mat.shear = option("SHEAr ON / SHEAr OFF", {"ON", "OFF"}) == "ON";
      }
    } else if (key == "smal" || key == "fini") {
      ctx.maxFields(r, 1, s->name);
      mat.kinematics = key == "smal" ? Kinematics::Small : Kinematics::Finite;
      kinematicsRec = &r;
    } else if (key == "dens") {
      const std::string syntax = "DENSity,,rho";
      numericText(syntax);
      if (!text2.empty()) failAt(r, 1, "DENSity takes no option", "write " + syntax);
      const auto v = values(2, 1, syntax);
      if (v[0] < 0) failAt(r, 2, "density must not be negative");
      if (v[1] != 0 && v[1] != 1)
        failAt(r, 3, "a rotary inertia factor other than 1 is not available");
      mat.density = v[0];
      densityRec = &r;
    } else if (key == "damp") {
      mat.dampingA1 = readDamping(ctx, r);
    } else if (key == "mass") {
      mat.mass = option("MASS LUMPed / MASS CONSistent", {"LUMPed", "CONSistent"}) == "LUMPed"
                     ? MassType::Lumped
                     : MassType::Consistent;
    } else if (key == "resu") {
      const std::string syntax = "RESUltant STIFfness EA GA EI";
      numericText(syntax);
      if (!keywordMatches(text2, "STIFfness"))
        failAt(r, 1, "expected STIFfness", "write " + syntax);
      const auto v = values(3, 3, syntax);
      if (v[0] <= 0) failAt(r, 2, "EA must be positive");
      if (v[1] < 0) failAt(r, 3, "GA must not be negative");
      if (v[2] <= 0) failAt(r, 4, "EI must be positive");
      mat.resEA = v[0];
      mat.resGA = v[1];
      mat.resEI = v[2];
      resultantRec = &r;
    } else {
      bindLawRecord(ctx, r, *s, mat, laws);
    }
  }

  finishLawRecords(h, laws, mat, elasticRec, sectionRec, resultantRec);
  warnSectionUnits(ctx, laws, mat);
  if (!mat.resEI) {
    if (!elasticRec)
      failAt(h, 0, "material " + std::to_string(m) + " has no ELAStic record",
             "give ELAStic ISOTropic E nu and CROSs SECTion A I, or RESUltant STIFfness EA GA EI");
    if (!sectionRec)
      failAt(h, 0, "material " + std::to_string(m) + " has no CROSs record",
             "give CROSs SECTion A I");
  } else if (mat.shear && *mat.resGA <= 0) {
    failAt(h, 0, "material " + std::to_string(m) + " has GA = 0 with shear deformation on",
           "give GA, or SHEAr OFF for Euler-Bernoulli");
  }
  if (densityRec && mat.density > 0 && mat.A <= 0)
    failAt(*densityRec, 2, "DENSity needs the section area: give CROSs SECTion A I too");

  if (auto* os = ctx.out()) echoMaterial(*os, mat);
  if (const MaterialSet* before = ctx.model.material(m)) {
    if (before->section || mat.section)
      failAt(h, 0, "material " + std::to_string(m) + " has or gets a SECTion: it cannot be given again",
             "an RC member's history belongs to its section");
    auto [it, added] = ctx.changedMaterials.try_emplace(m);
    if (added) it->second.before = before->kinematics;  // as the existing elements have it
    it->second.head = h;
    it->second.kinematics = kinematicsRec ? *kinematicsRec : Record{};
  }
  ctx.model.materials()[m] = mat;
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
