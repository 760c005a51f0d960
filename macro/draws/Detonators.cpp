#include "macro/draws/Detonators.h"

#include <algorithm>
#include <cmath>

#include "macro/draws/CounterRandom.h"
#include "macro/draws/Distribution.h"

namespace c2d {

std::vector<double> scatterBlasts(Model& model, const DetonatorSpec& spec, std::uint64_t seed,
                                  int sample) {
  std::vector<double> times;
  const std::uint64_t stream = streamOf("detonator");
  std::uint64_t r = 0;
  for (Blast& b : model.blasts()) {
    const double sigma = std::hypot(spec.sd, spec.cov * b.time);
    const double z = normalQuantile(counterUniform(seed, sample, stream, r++));
    b.time = std::max(0.0, b.time + sigma * z);
    times.push_back(b.time);
  }
  return times;
}

}  // namespace c2d
