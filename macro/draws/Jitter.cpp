#include "macro/draws/Jitter.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <vector>

#include "macro/draws/CounterRandom.h"

namespace c2d {

void jitterNodes(Model& model, const JitterSpec& jitter, std::uint64_t seed, int sample) {
  const int nn = model.numNodes();
  std::vector<int> order;
  for (int n = 0; n < nn; ++n)
    if (model.hasCoord(n)) order.push_back(n);
  // Groups of coincident nodes: sorted by x, each node is joined to the earlier
  // ones within the tolerance in both coordinates; a group's offset is keyed by
  // its lowest node number.
  const double tol = 1e-9 * model.characteristicLength();
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return model.coord(a).x() < model.coord(b).x(); });
  std::vector<int> parent(static_cast<std::size_t>(nn));
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int n) {
    while (parent[n] != n) n = parent[n] = parent[parent[n]];
    return n;
  };
  for (std::size_t i = 0; i < order.size(); ++i)
    for (std::size_t j = i; j-- > 0;) {
      const int n = order[i], m = order[j];
      if (model.coord(n).x() - model.coord(m).x() > tol) break;
      if (std::abs(model.coord(n).y() - model.coord(m).y()) <= tol) {
        const int a = root(n), b = root(m);
        parent[std::max(a, b)] = std::min(a, b);  // the root is the lowest number
      }
    }
  std::vector<int> group(static_cast<std::size_t>(nn), -1);
  for (int n : order) group[n] = root(n);
  const std::uint64_t stream = streamOf("jitter");
  for (int n : order) {
    const auto g = static_cast<std::uint64_t>(group[n]);
    const double r = jitter.dx * std::sqrt(counterUniform(seed, sample, stream, 2 * g));
    const double phi = 2 * std::numbers::pi * counterUniform(seed, sample, stream, 2 * g + 1);
    model.setCoord(n, model.coord(n) + Vec2(r * std::cos(phi), r * std::sin(phi)));
  }
}

double stepFactor(const JitterSpec& jitter, std::uint64_t seed, int sample) {
  return 1 + jitter.fdt * (2 * counterUniform(seed, sample, streamOf("jitter.dt"), 0) - 1);
}

}  // namespace c2d
