#include "macro/mesh/BlastCommand.h"

#include <cmath>
#include <iomanip>
#include <ostream>

#include "macro/deck/NumberRanges.h"

namespace c2d {

using namespace meshspec;

namespace {

// The ON field of a BLASt record: 1 (absent or empty) the record blasts, 0 it
// does not (a plan of a study without this blast). Any other value is an error,
// so that a shifted field is not read as a switch.
bool blastOn(const MeshContext& ctx, const Record& r) {
  if (r.text(5).empty()) return true;
  const double on = ctx.number(r, 5);
  if (on != 0 && on != 1)
    failAt(r, 5, "the ON field of a BLASt record is 1 (blast) or 0 (no blast), not " + r.text(5),
           "a parameter that is 0 or 1 in each plan switches a blast of a study on or off");
  return on == 1;
}

// BLASt: t n1 n2 inc td on. Elements are built when the mesh is complete, so the
// records are checked and added then (in deck order). A record switched off is
// echoed as such and checked no further: a plan may leave its numbers unset.
void applyBlasts(MeshContext& ctx, const MeshCommand& cmd) {
  const std::string syntax = "t n1 n2 inc td on";
  if (cmd.data.empty())
    failAt(cmd.head, 0, "BLASt needs data records '" + syntax + "' up to a blank record");
  for (const Record& r : cmd.data) {
    ctx.maxFields(r, 6, syntax);
    if (!blastOn(ctx, r)) {
      if (auto* os = ctx.out()) *os << "      BLASt  off (ON = 0): " << r.lineText() << "\n";
      continue;
    }
    const double t = ctx.number(r, 0);
    if (!std::isfinite(t) || t < 0) failAt(r, 0, "the blast time must be zero or positive");
    // Plain variables, not a structured binding: the deferred lambda captures them.
    const auto range = ctx.elementRange(r, 1, false);
    const int n1 = range.n1, n2 = range.n2, inc = range.inc;
    const double td = ctx.number(r, 4);
    if (!std::isfinite(td) || td < 0)
      failAt(r, 4, "the release time td must be zero or positive",
             "td = 0 removes the forces at once; GSA 2016 asks for at most a tenth of the "
             "structure's first vertical period");
    ctx.deferred.push_back([=](MeshContext& c) {
      Blast b;
      b.time = t;
      b.release = td;
      b.origin = r[0].loc;
      // The first element beyond the mesh, before the range is generated.
      if (const long long first = firstBeyond(n1, n2, inc, c.model.numElements()))
        failAt(r, first == n1 ? 1 : 2,
               "BLASt: element " + std::to_string(first) + " is not defined");
      for (int e : steppedRange(n1, n2, inc)) {
        if (e > c.model.numElements() || !c.model.hasElement(e - 1))
          failAt(r, e == n1 ? 1 : 2, "BLASt: element " + std::to_string(e) + " is not defined");
        for (const Blast& other : c.model.blasts())
          for (int o : other.elements)
            if (o == e - 1)
              failAt(r, e == n1 ? 1 : 2,
                     "BLASt: element " + std::to_string(e) +
                         " is already removed by an earlier "
                         "record (at t = " +
                         std::to_string(other.time) + ")");
        b.elements.push_back(e - 1);
      }
      if (auto* os = c.out()) {
        *os << "      BLASt  t = " << std::setw(13) << std::scientific << std::setprecision(4) << t
            << "  td = " << std::setw(13) << td << "  elements";
        for (int e : b.elements) *os << ' ' << e + 1;
        *os << "\n";
      }
      c.model.blasts().push_back(std::move(b));
    });
  }
}

}  // namespace

std::vector<MeshCommandEntry> blastCommandTable() {
  std::vector<MeshCommandEntry> t;
  t.push_back(
      {meshSpec(
           "BLASt",
           "Blast plan of a demolition: elements n1..n2 with step inc are removed at time "
           "t (their stiffness, mass, self-weight, floor loads and contact leave the model; "
           "a node no element holds any more leaves it too); the forces they exerted on the "
           "rest are released linearly over td (0 or empty: at once; GSA 2016: td at most a "
           "tenth of the first vertical period). Steps end exactly on every t and t + td. "
           "One log line per blast (a blast the run never reaches is warned at its end); the "
           "energy they carried is booked as dissipated, the work of the released forces as "
           "external. Under arc length a blast happens at "
           "the first step past its time. REMOve,ELEMents removes at the current time. "
           "The ON field switches a record off (0; 1 or empty: on): a study whose plans blast "
           "different column lines gives each line a record and each plan its switches "
           "(SWEEp), and a record switched off blasts nothing, is checked no further and is "
           "not warned about; DETOnators draw for the records that are on, blast_1, blast_2, "
           "... in their order.",
           {}, "t n1 n2 inc td on",
           {expr("t", "blast time"), expr("n1", "first element"), expr("n2", "last element", "n1"),
            expr("inc", "element step", "1"), expr("td", "release time of the forces", "0"),
            expr("on", "1: this record blasts, 0: it does not", "1")}),
       applyBlasts});
  return t;
}

}  // namespace c2d
