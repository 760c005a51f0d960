#include "elements/MaterialUpdate.h"

#include <algorithm>

#include "core/MaterialChange.h"

namespace c2d {

Status changeMaterial(Model& model, const State& state, const MaterialSet& mat,
                      const std::vector<int>& skip) {
  bool changed = false;
  for (int e = 0; e < model.numElements(); ++e) {
    if (!model.elements()[e] || model.element(e).materialNumber() != mat.number) continue;
    if (std::find(skip.begin(), skip.end(), e) != skip.end()) continue;
    Element& el = model.element(e);
    auto* target = dynamic_cast<MaterialChange*>(&el);
    const std::string who = "element " + std::to_string(e + 1) + ": ";
    if (!target)
      return Status::failure(who + "element type '" + el.typeName() + "' keeps its material");
    ElemVec d = ElemVec::Zero();
    for (int a = 0; a < 2; ++a) {
      const Eigen::Index base = static_cast<Eigen::Index>(el.nodes()[a]) * kNodeDofs;
      if (base + kNodeDofs <= state.un.size())
        d.segment<kNodeDofs>(a * kNodeDofs) = state.un.segment<kNodeDofs>(base);
    }
    if (Status st = target->setMaterial(mat, d); !st) {
      if (changed) model.bumpTopology();
      return Status::failure(who + st.why);
    }
    changed = true;
  }
  if (changed) model.bumpTopology();
  return Status::success();
}

}  // namespace c2d
