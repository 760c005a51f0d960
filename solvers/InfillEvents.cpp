#include "solvers/InfillEvents.h"

#include <algorithm>

#include "elements/InfillStrut.h"

namespace c2d {

void InfillEvents::afterCommit(Model& model, double time) {
  if (indexedModel_ != &model || indexedVersion_ != model.topologyVersion()) {
    indexedModel_ = &model;
    indexedVersion_ = model.topologyVersion();
    struts_.clear();
    for (int e = 0; e < model.numElements(); ++e)
      if (model.hasElement(e))
        if (auto* s = dynamic_cast<InfillStrut*>(&model.element(e)))
          if (std::find(reportedPanels_.begin(), reportedPanels_.end(), s->data().panel) ==
              reportedPanels_.end())
            struts_.emplace_back(e, s);
  }
  for (auto& [e, s] : struts_) {
    if (!s || !s->gone()) continue;
    const int panel = s->data().panel, partner = s->data().partner;
    if (partner >= 0 && partner < model.numElements() && model.hasElement(partner))
      if (auto* p = dynamic_cast<InfillStrut*>(&model.element(partner))) p->doom();
    for (auto& other : struts_)
      if (other.second && other.second->data().panel == panel) other.second = nullptr;
    reportedPanels_.push_back(panel);
    if (onEvent) onEvent(InfillEvent{panel, e, partner, time});
  }
}

}  // namespace c2d
