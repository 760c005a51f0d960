#pragma once
// One node-segment pair of the member contact (docs/design/member-contact.md):
// a node and an element it does not belong to, with their contact distance.
#include <cstdint>

namespace c2d {

struct ContactPair {
  int node = -1, element = -1;
  int a = -1, b = -1;  // the element's nodes
  double h = 0;        // contact distance
  std::uint64_t key() const {
    return (static_cast<std::uint64_t>(node) << 32) | static_cast<std::uint32_t>(element);
  }
};

}  // namespace c2d
