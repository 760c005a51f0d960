#pragma once
// [ext] JITTer,,dx,fdt of an ENSEmble: the perturbation that makes the chaos of
// a collapse visible. Each sample moves every node by its own random offset,
// uniform over the disc of radius dx (the deck's length unit), before the
// elements are built (their reference geometry is the moved one), and scales
// every time step the deck sets (DT, BACK) in a dynamic analysis by a factor
// uniform in [1 - fdt, 1 + fdt] (a static analysis's steps are a load path
// whose step counts reach the deck's load levels: they are kept). Coincident nodes (a joint's
// master and slave, within 1e-9 of the mesh size) move together, by the offset of the
// lowest-numbered. Defaults: dx = 1e-6 (1 um in a deck in metres: round-off's size, far below any
// tolerance), fdt = 0.01 (steps 1 % longer or shorter: a change of the
// discretization error's order that leaves the run's convergence alone).
#include <cstdint>

#include "core/Model.h"

namespace c2d {

struct JitterSpec {
  static constexpr double kDefaultDx = 1e-6, kDefaultFdt = 0.01;
  double dx = kDefaultDx, fdt = kDefaultFdt;
};

// Moves the nodes with coordinates (the mesh input's) of sample `sample`.
void jitterNodes(Model& model, const JitterSpec& jitter, std::uint64_t seed, int sample);
// The factor of the sample's time steps, in [1 - fdt, 1 + fdt].
double stepFactor(const JitterSpec& jitter, std::uint64_t seed, int sample);

}  // namespace c2d
