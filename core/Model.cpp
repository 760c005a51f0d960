#include "core/Model.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace c2d {

void Model::resizeNodes(int n) {
  coords_.resize(n, Vec2::Zero());
  defined_.resize(n, 0);
  bound_.resize(n, {0, 0, 0});
  table_.resize(n, {0, 0, 0});
  force_.resize(n, {0, 0, 0});
  disp_.resize(n, {0, 0, 0});
  mass_.resize(n, {0, 0, 0});
}

int Model::addNode(const Vec2& x) {
  const Vec2 position = x;  // x may refer into coords_, which the resize moves
  const int n = numNodes();
  resizeNodes(n + 1);
  coords_[n] = position;
  defined_[n] = 1;
  return n;
}

const MaterialSet* Model::material(int number) const {
  auto it = materials_.find(number);
  return it == materials_.end() ? nullptr : &it->second;
}

void Model::setElement(int e, std::unique_ptr<Element> el) {
  if (e >= numElements()) elements_.resize(e + 1);
  elements_[e] = std::move(el);
}

std::unique_ptr<Element> Model::removeElement(int e) {
  std::unique_ptr<Element> el = std::move(elements_[e]);
  bumpTopology();
  return el;
}

std::vector<char> Model::heldNodes() const {
  std::vector<char> held(coords_.size(), 0);
  for (const auto& el : elements_)
    if (el)
      for (int n : el->nodes()) held[n] = 1;
  return held;
}

double Model::characteristicLength() const {
  double shortest = std::numeric_limits<double>::infinity();
  for (const auto& el : elements_) {
    if (!el) continue;
    auto n = el->nodes();
    shortest = std::min(shortest, (coords_[n[0]] - coords_[n[1]]).norm());
  }
  if (std::isfinite(shortest) && shortest > 0) return shortest;
  double extent = 0;
  for (const auto& x : coords_) extent = std::max(extent, x.cwiseAbs().maxCoeff());
  return extent > 0 ? extent : 1.0;
}

}  // namespace c2d
