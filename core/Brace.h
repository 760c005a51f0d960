#pragma once
// An element that braces its nodes without being a member: an infill panel's
// diagonal strut (elements/InfillStrut.h). It strikes nothing (member contact
// leaves it out; ground contact is the nodes'), it is no piece of the debris
// (its mass lies at its nodes and joins no pieces), and it carries no moment.
#include "core/Element.h"

namespace c2d {

class Brace {
 public:
  virtual ~Brace() = default;
};

inline bool isBrace(const Element& e) { return dynamic_cast<const Brace*>(&e) != nullptr; }

}  // namespace c2d
