#include "elements/ElementFactory.h"

#include "elements/InelasticFrame.h"
#include "elements/Joints.h"
#include "elements/LinearFrame.h"
#include "elements/ReissnerFrame.h"

namespace c2d {

std::unique_ptr<Element> makeElement(const MaterialSet& mat, const std::array<int, 2>& nodes,
                                     const Vec2& x1, const Vec2& x2,
                                     const std::array<double, 2>& offsets) {
  if (mat.kinematics == Kinematics::Finite)
    return std::make_unique<ReissnerFrame>(mat, nodes, x1, x2, offsets);
  if (mat.hardening || mat.softening)
    return std::make_unique<InelasticFrame>(mat, nodes, x1, x2, offsets);
  return std::make_unique<LinearFrame>(mat, nodes, x1, x2, offsets);
}

std::array<double, 2> rigidOffsets(const Element& e) {
  const Element& in = innermost(e);
  if (const auto* f = dynamic_cast<const LinearFrame*>(&in)) return f->rigidEnds().offsets();
  if (const auto* f = dynamic_cast<const InelasticFrame*>(&in)) return f->rigidEnds().offsets();
  if (const auto* f = dynamic_cast<const ReissnerFrame*>(&in)) return f->rigidEnds().offsets();
  return {0.0, 0.0};
}

}  // namespace c2d
