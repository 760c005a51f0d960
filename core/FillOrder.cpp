#include "core/FillOrder.h"

#include <amd.h>

#include <algorithm>

namespace c2d {

std::vector<int> fillReducingOrder(std::vector<std::vector<int>>& adjacency) {
  const int n = static_cast<int>(adjacency.size());
  std::vector<int> Ap(n + 1, 0), Ai;
  for (int i = 0; i < n; ++i) {
    auto& a = adjacency[i];
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
    Ap[i + 1] = Ap[i] + static_cast<int>(a.size());
    Ai.insert(Ai.end(), a.begin(), a.end());
  }
  if (Ai.empty()) return {};
  std::vector<int> perm(n);
  if (amd_order(n, Ap.data(), Ai.data(), perm.data(), nullptr, nullptr) < AMD_OK) return {};
  return perm;
}

}  // namespace c2d
