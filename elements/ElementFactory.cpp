#include "elements/ElementFactory.h"

#include "elements/InelasticFrame.h"
#include "elements/LinearFrame.h"
#include "elements/ReissnerFrame.h"

namespace c2d {

std::unique_ptr<Element> makeElement(const MaterialSet& mat, const std::array<int, 2>& nodes,
                                     const Vec2& x1, const Vec2& x2) {
  if (mat.kinematics == Kinematics::Finite)
    return std::make_unique<ReissnerFrame>(mat, nodes, x1, x2);
  if (mat.hardening || mat.softening) return std::make_unique<InelasticFrame>(mat, nodes, x1, x2);
  return std::make_unique<LinearFrame>(mat, nodes, x1, x2);
}

}  // namespace c2d
