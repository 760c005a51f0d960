#include "macro/mesh/BlastOfRemoved.h"

#include <algorithm>
#include <string>
#include <variant>

#include "macro/deck/NumberRanges.h"

namespace c2d {

namespace {

struct Removal {
  const Macro* command;
  std::vector<int> elements;  // 0-based, sorted
};

// The elements of a REMOve,ELEMents,n1,n2,inc (as the run takes them); none
// when a number cannot be evaluated here (the run reports it at the command).
std::vector<int> removedBy(const Macro& m, const Parameters& params) {
  std::vector<int> out;
  try {
    const int n1 = m.numbers.at(0).evalInt(params, "first element");
    const int n2 =
        m.has(1) && !m.record.text(3).empty() ? m.numbers[1].evalInt(params, "last element") : n1;
    int inc = m.has(2) && !m.record.text(4).empty() ? m.numbers[2].evalInt(params, "increment") : 1;
    if (inc <= 0) inc = 1;
    for (int e : steppedRange(std::max(n1, 1), n2, inc)) out.push_back(e - 1);
  } catch (const std::exception&) {
    out.clear();
  }
  return out;
}

void collectRemovals(const std::vector<Macro>& list, const Parameters& params,
                     std::vector<Removal>& out) {
  for (const Macro& m : list) {
    if (m.is("remo")) out.push_back({&m, removedBy(m, params)});
    collectRemovals(m.body, params, out);
  }
}

// The text of the record at loc among the problem's BLASt records (empty if none).
std::string blastText(const Problem& problem, const SourceLoc& loc) {
  for (const MeshItem& item : problem.mesh) {
    const auto* cmd = std::get_if<MeshCommand>(&item);
    if (!cmd || !cmd->head.is("BLASt")) continue;
    for (const Record& r : cmd->data)
      if (!r.blank() && r[0].loc.str() == loc.str()) return r.excerpt(loc);
  }
  return {};
}

}  // namespace

void warnBlastsOfRemovedElements(const Problem& problem, const Model& model,
                                 const std::vector<std::vector<Macro>>& batches,
                                 const Parameters& params, Warnings* warnings) {
  if (!warnings || model.blasts().empty()) return;
  std::vector<Removal> removals;
  for (const auto& batch : batches) collectRemovals(batch, params, removals);
  for (const Blast& b : model.blasts()) {
    if (b.origin.file.empty()) continue;
    for (const Removal& r : removals) {
      const auto both = std::find_first_of(b.elements.begin(), b.elements.end(), r.elements.begin(),
                                           r.elements.end());
      if (both == b.elements.end()) continue;
      warnings->add(b.origin,
                    "BLASt of element " + std::to_string(*both + 1) + ", which the REMOve of " +
                        r.command->record.fieldLoc(0).str() +
                        " removes too: whichever comes first takes it out, and then the blast "
                        "removes nothing of it or the REMOve fails",
                    blastText(problem, b.origin));
      break;
    }
  }
}

}  // namespace c2d
