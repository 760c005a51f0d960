#include "macro/mesh/MasslessLoads.h"

#include <string>
#include <variant>

namespace c2d {

namespace {

// The first command that makes the analysis dynamic, in execution order.
const Macro* firstDynamic(const std::vector<Macro>& list) {
  for (const Macro& m : list) {
    if ((m.is("dyna") || m.is("tran")) && m.option.rfind("off", 0) != 0) return &m;
    if (const Macro* inner = firstDynamic(m.body)) return inner;
  }
  return nullptr;
}

}  // namespace

void warnMasslessFloorLoads(const Problem& problem, const std::vector<std::vector<Macro>>& batches,
                            Warnings* warnings) {
  if (!warnings) return;
  const Macro* dynamic = nullptr;
  for (const auto& batch : batches)
    if (!dynamic) dynamic = firstDynamic(batch);
  if (!dynamic) return;
  for (const MeshItem& item : problem.mesh) {
    const auto* cmd = std::get_if<MeshCommand>(&item);
    if (!cmd || !cmd->head.is("QLOAd")) continue;
    for (const Record& r : cmd->data)
      if (r.size() < 6 || r[5].text.empty()) {
        warnings->add(r.fieldLoc(0),
                      "a floor load without MASS in a dynamic run (" + dynamic->record.text(0) +
                          " on line " + std::to_string(dynamic->record.loc.line) +
                          "): its weight acts on members that do not carry its mass (QLOAd ... "
                          "MASS makes it both)",
                      r.excerpt(r.fieldLoc(0)));
        return;
      }
  }
}

}  // namespace c2d
