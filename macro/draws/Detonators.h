#pragma once
// [ext] DETOnators of an ENSEmble: every BLASt record's time scattered
// independently in each sample, as the delay of a real detonator scatters
// about its nominal value. The time of record r in sample k is
//   t_r + sigma z,  sigma = sqrt(sd^2 + (cov t_r)^2),
// z a standard normal number of (seed, k, r) (the nominal delay counted from
// t = 0), and never below 0. The time unit is the deck's (seconds in the
// demolition decks; the defaults assume seconds).
//   DETOnators,,sd,cov   as given
//   DETOnators,ELECtronic  sd = 1 ms: electronic delay detonators keep their
//       programmed delay to 0.5-1 ms (C. Pretorius, "Electronic delay
//       detonators", Institute of Quarrying, 2008: "an accuracy of between 0.5
//       and 1.0 milliseconds, about 50 times more accurate than pyrotechnic
//       delays"); the upper figure is taken.
//   DETOnators,PYROtechnic cov = 3 %: a pyrotechnic delay element burns to
//       within a few per cent of its nominal delay (delay compositions are
//       made to burn within +-5 %; about 50 times the electronic scatter, as
//       above, is 2.5 % of a 2 s delay); 3 % of the nominal delay is the
//       standard deviation taken.
#include <cstdint>
#include <vector>

#include "core/Model.h"

namespace c2d {

struct DetonatorSpec {
  static constexpr double kElectronicSd = 1e-3;    // s
  static constexpr double kPyrotechnicCov = 0.03;  // of the nominal delay
  double sd = 0, cov = 0;
};

// The blast times of sample `sample`, one per BLASt record (the model's blasts
// in deck order), set in the model; returns them.
std::vector<double> scatterBlasts(Model& model, const DetonatorSpec& spec, std::uint64_t seed,
                                  int sample);

}  // namespace c2d
