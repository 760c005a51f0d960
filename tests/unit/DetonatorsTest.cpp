// The detonators' scatter of the blast times (macro/studies/Detonators): each
// record its own detonator, pyrotechnic delays normal about the nominal time,
// electronic ones never before t = 0.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "core/Model.h"
#include "macro/draws/Detonators.h"
#include "macro/draws/Distribution.h"
#include "tests/unit/EnsembleTestSupport.h"

namespace c2d {
namespace {

using testing::ksCritical;
using testing::ksStatistic;

TEST(EnsembleDraws, DetonatorsScatterEachBlastTime) {
  // Pyrotechnic: sd 3 % of the nominal delay; electronic: 1 ms.
  auto scatter = [](const DetonatorSpec& spec, double t, int n) {
    std::vector<double> times;
    for (int k = 1; k <= n; ++k) {
      Model m;
      m.blasts().push_back({t, {0}, 0, false, {}});
      m.blasts().push_back({t, {1}, 0, false, {}});
      const std::vector<double> drawn = scatterBlasts(m, spec, 1, k);
      EXPECT_EQ(drawn.size(), 2u);
      if (drawn[0] > 0) {
        EXPECT_NE(drawn[0], drawn[1]);  // each record its own detonator
      }
      EXPECT_EQ(m.blasts()[0].time, drawn[0]);
      times.push_back(drawn[0]);
    }
    return times;
  };
  DetonatorSpec pyro;
  pyro.cov = DetonatorSpec::kPyrotechnicCov;
  const std::vector<double> p = scatter(pyro, 2.0, 1000);
  const Distribution law{Law::Normal, 2.0, 0.06};
  EXPECT_LT(ksStatistic(p, [&](double v) { return law.cdf(v); }), ksCritical(1000));
  DetonatorSpec elec;
  elec.sd = DetonatorSpec::kElectronicSd;
  const std::vector<double> e = scatter(elec, 1e-4, 500);
  EXPECT_GE(*std::min_element(e.begin(), e.end()), 0.0);  // never before t = 0
}

}  // namespace
}  // namespace c2d
