#include "macro/mesh/WeakenCommand.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <ostream>
#include <stdexcept>

#include "elements/ElementFactory.h"
#include "elements/InfillStrut.h"
#include "macro/deck/NumberRanges.h"
#include "materials/WeakenedSet.h"

namespace c2d {

using namespace meshspec;

namespace {

int nextMaterialNumber(const Model& model) {
  return model.materials().empty() ? 1 : model.materials().rbegin()->first + 1;
}

// Weakens element e (0-based) of record r (field: the number's); sets: the
// weakened copies this record made, by original set.
void weakenElement(MeshContext& ctx, const Record& r, std::size_t field, int e, double f,
                   std::map<int, int>& sets) {
  Model& model = ctx.model;
  const std::string what = "WEAKen: element " + std::to_string(e + 1);
  if (e >= model.numElements() || !model.hasElement(e))
    failAt(r, field, what + " is not defined");
  if (e < ctx.elementsBefore)
    failAt(r, field, what + " existed before this MESH re-entry: WEAKen acts from the start",
           "weaken it in the mesh input that made it");
  Element& el = model.element(e);
  if (auto* strut = dynamic_cast<InfillStrut*>(&el)) {
    strut->weaken(f);
    return;
  }
  const MaterialSet* mat = model.material(el.materialNumber());
  if (!mat) failAt(r, field, what + " has no material set: it cannot be weakened");
  auto it = sets.find(mat->number);
  if (it == sets.end()) {
    const int number = nextMaterialNumber(model);
    try {
      model.materials()[number] = weakenedSet(*mat, f, number);
    } catch (const std::invalid_argument& ex) {
      failAt(r, field, what + " cannot be weakened: " + ex.what());
    }
    it = sets.emplace(mat->number, number).first;
  }
  const auto nodes = el.nodes();
  model.setElement(e, makeElement(*model.material(it->second), nodes, model.coord(nodes[0]),
                                  model.coord(nodes[1]), rigidOffsets(el)));
}

void applyWeaken(MeshContext& ctx, const MeshCommand& cmd) {
  const std::string syntax = "factor n1 n2 inc";
  if (cmd.data.empty())
    failAt(cmd.head, 0, "WEAKen needs data records '" + syntax + "' up to a blank record");
  for (const Record& r : cmd.data) {
    ctx.maxFields(r, 4, syntax);
    const double f = ctx.number(r, 0);
    if (!(f > 0 && f <= 1))
      failAt(r, 0, "the share kept must lie in (0, 1]",
             "1 keeps the element as it is; to take it out use REMOve or BLASt");
    // Plain variables, not a structured binding: the deferred lambda captures them.
    const auto range = ctx.elementRange(r, 1, false);
    const int n1 = range.n1, n2 = range.n2, inc = range.inc;
    ctx.deferred.push_back([=, &r](MeshContext& c) {
      if (const long long first = firstBeyond(n1, n2, inc, c.model.numElements()))
        failAt(r, first == n1 ? 1 : 2, "WEAKen: element " + std::to_string(first) + " is not defined");
      std::map<int, int> sets;
      for (int e : steppedRange(n1, n2, inc)) {
        const std::size_t field = e == n1 ? 1 : 2;
        auto& done = c.weakened;
        if (const auto w = done.find(e); w != done.end())
          failAt(r, field,
                 "WEAKen: element " + std::to_string(e) + " is already weakened (line " +
                     std::to_string(w->second) + ")",
                 "give each element one factor: the share it keeps from the start");
        done[e] = r.loc.line;
        weakenElement(c, r, field, e - 1, f, sets);
      }
      if (auto* os = c.out()) {
        *os << "      WEAKen  factor ";
        num(*os, f) << "  elements " << n1 << " to " << n2 << " step " << inc;
        for (const auto& [from, to] : sets) *os << "  (set " << from << " -> set " << to << ")";
        *os << "\n";
      }
    });
  }
}

}  // namespace

std::vector<MeshCommandEntry> weakenCommandTable() {
  std::vector<MeshCommandEntry> t;
  t.push_back(
      {meshSpec("WEAKen",
                "Elements n1..n2 with step inc (members or INFIll struts) keep the share factor "
                "(0 < factor <= 1) of their strength and stiffness from the start: walls cut, "
                "cores opened, bars cut before the blast. A member takes a copy of its material "
                "set numbered after the deck's sets (the echo says which), exactly a weaker "
                "set: SECTion: b, the bars' and the stirrups' areas times factor (EA, GA, EI, "
                "every moment, the axial and shear capacities scale by factor at factor times "
                "the axial force; the mass stays); hand-given laws: E or EA, GA, EI, and every "
                "moment and modulus of HARDening, SOFTening and INTEraction times factor "
                "(rotations stay). An INFIll strut scales its stiffness and strength. Each "
                "element once; applied when the mesh is complete; not in a MESH re-entry for "
                "elements made before it.",
                {}, "factor n1 n2 inc",
                {expr("factor", "share of strength and stiffness kept (0..1]"),
                 expr("n1", "first element"), expr("n2", "last element", "n1"),
                 expr("inc", "element step", "1")}),
       applyWeaken});
  return t;
}

}  // namespace c2d
