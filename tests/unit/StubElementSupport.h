#pragma once
// A stub element for tests that need an element of a given residual only:
// nodes {0, 1} unless given (settable), a material number and a type name;
// no mass, no body load, no state to commit or revert, no strain energy and
// zero section forces. A test's element derives from it and gives evaluate().
#include <array>
#include <string>
#include <utility>

#include "core/Element.h"

namespace c2d::test {

class StubElement : public Element {
 public:
  explicit StubElement(std::string type, int material = 1, std::array<int, 2> nodes = {0, 1})
      : type_(std::move(type)), material_(material), nodes_(nodes) {}
  std::array<int, 2> nodes() const override { return nodes_; }
  void setNodes(const std::array<int, 2>& n) override { nodes_ = n; }
  int materialNumber() const override { return material_; }
  std::string typeName() const override { return type_; }
  ElemMat mass() const override { return ElemMat::Zero(); }
  ElemVec bodyLoad(const Vec2&) const override { return ElemVec::Zero(); }
  void commit() override {}
  void revert() override {}
  double strainEnergy() const override { return 0; }
  SectionForces sectionForces() const override { return {}; }

 private:
  std::string type_;
  int material_;
  std::array<int, 2> nodes_;
};

}  // namespace c2d::test
