#pragma once
// Infill panels that crush during a run (elements/InfillStrut.h). After a
// commit, a strut that has gone (crushed past its residual) dooms its panel's
// other strut, which goes as soon as it carries nothing (materials/StrutLaw.h):
// a crushed panel no longer braces its bay, and no force jumps. Each panel is
// reported once, when its first strut goes.
#include <functional>
#include <vector>

#include "core/Model.h"

namespace c2d {

class InfillStrut;

struct InfillEvent {
  int panel = 0;                    // 1-based, as the mesh echo numbers them
  int element = -1, partner = -1;   // 0-based: the strut that went, the other one
  double time = 0;
};

class InfillEvents {
 public:
  std::function<void(const InfillEvent&)> onEvent;
  // At every commit (time: the committed time). Allocates only when the
  // topology changed (the struts are indexed once per topology version).
  void afterCommit(Model& model, double time);

 private:
  const Model* indexedModel_ = nullptr;
  int indexedVersion_ = -1;
  std::vector<std::pair<int, InfillStrut*>> struts_;  // (element, strut) not yet reported
  std::vector<int> reportedPanels_;
};

}  // namespace c2d
