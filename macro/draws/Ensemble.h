#pragma once
// [ext] The ENSEmble block: a plan decided on distributions. Before a problem
// (and its SWEEp, before or after it):
//   ENSEmble,,n,seed
//     mu = UNIForm 0.4 0.6        ! drawn parameters (macro/draws/Distribution.h)
//     fMu = LOGNormal 1 0.1
//     JITTer,,dx,fdt              ! node offsets and time-step factor (Jitter.h)
//     DETOnators,PYROtechnic      ! BLASt times scattered (Detonators.h)
//   <blank record>
// Every plan (every value set of the sweep, or the lone problem) runs n times;
// sample k (1..n) takes the draws of (seed, k) alone (CounterRandom.h): the
// same in every plan, in every shard and in every rerun. A drawn name is a
// parameter like any other, set after the sweep's values and before the
// PARAmeter blocks between the block and the problem (which may derive from
// it, and may not set it again).
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "macro/deck/Deck.h"
#include "macro/draws/Detonators.h"
#include "macro/draws/Distribution.h"
#include "macro/draws/Jitter.h"

namespace c2d {

struct NamedDraw {
  std::string name;  // as written
  Distribution law;
};

struct EnsembleSpec {
  int samples = 1;
  std::uint64_t seed = 1;
  std::vector<NamedDraw> draws;
  std::optional<JitterSpec> jitter;
  std::optional<DetonatorSpec> detonators;
};

// The block's numbers evaluated with the parameters (DeckError at a bad value).
EnsembleSpec evaluateEnsemble(const TopEnsemble& ensemble, const Parameters& params);

// The plans of a study are compared on paired runs (sample k of every plan
// takes the draws of (seed, k)): every plan walked must take the same n and
// seed. A plan whose n or seed differs from the first plan's (swept, or derived
// from a swept value) is a DeckError at that field, found by the check pass
// before any run.
class EnsemblePairing {
 public:
  // plan: 1, 2, ... in walk order.
  void check(const TopEnsemble& ensemble, const EnsembleSpec& spec, int plan);

 private:
  bool seen_ = false;
  int samples_ = 0;
  std::uint64_t seed_ = 0;
  int plan_ = 0;
};

// What sample k of an ensemble draws.
struct SampleDraws {
  int sample = 0;  // 1..n
  std::uint64_t seed = 1;
  std::vector<std::pair<std::string, double>> values;  // the drawn parameters, in record order
  double stepFactor = 1;                               // JITTer's time-step factor
  std::optional<JitterSpec> jitter;
  std::optional<DetonatorSpec> detonators;
};
SampleDraws drawSample(const EnsembleSpec& spec, int sample);

}  // namespace c2d
