// RC members in tension bend: a cantilever of the section of verification.md
// V20 (0.5 x 0.5 m, 4 bars of 20 mm at 0.05 m from each face) with mean
// strengths (fc = 38 MPa, fy = 550 MPa), under an axial tension applied
// first, then pushed 10 mm per step at its tip to 0.1 m (past the hinge's
// opening at its base), at five tensions from 0 to 0.95 of the bars' yield
// force Nt = As fy = 1382.3 kN, small and finite rotations, plain Newton
// (TANG,,1, no step cutting). Every step converges; near the solution the
// convergence is quadratic: with the residuals e_k of a step scaled by its
// largest after the first iteration, e_{k+1} <= 10 e_k^2 wherever e_k < 1e-2
// (in the iteration histories that converged).
//
// Before, with finite rotations, 50-500 kN of tension failed in the first
// push steps: the elastic predictor put the base sections just past first
// yield (tension lowers My by 0.2 m per kN here), onto the law's almost flat
// branch up to Mu (Kh2 ~ 150-180 kN m^2, EI = 2.1e5), and the next correction
// was a curvature jump of 0.15 1/m that turned elements by tenths of a
// radian and stretched them past the bars' yield: a period-three cycle or a
// run-away. The section's laws and the elements' tangents were right (their
// derivatives agree with central differences, RcMemberTest); the static
// Newton driver now restarts such a step with its line search
// (solvers/ConvergenceTest.h runsAway, period-three cycles).
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

std::string cantilever(const std::string& kinematics, double tension) {
  std::ostringstream d;
  d << "PARAmeter\n  H = 3\n  n = 6\n  A = 4*3.14159265358979*0.01^2\n  Nx = " << tension
    << "\n\nFEAP * * RC cantilever in tension pushed at its tip\n  0 0 0 2 3 2\n\n"
       "COORdinates\n  1 1 0 0\n  n+1 0 0 H\n\nELEMents\n  1 1 1 1 2\n  n 1 1 n n+1\n\n"
       "MATErial,1 column\n  FRAMe\n    SECTion RECTangular 0.5 0.5 38e3 550e3\n"
       "    REBAr 0.05 A 0.45 A\n    "
    << kinematics
    << "\n\nBOUNdary\n  1 0 1 1 1\n  n+1 0 1 0 0\n\nFORCe\n  n+1 0 0 Nx 0\n\n"
       "DISPlacement\n  n+1 0 1 0 0\n\nFPROportional\n  n+1 0 2 1 1\n\nEND\nBATCh\n"
       "  PROP,,1\n  PROP,,2\n  DT,,1\n  TIME\n  LOOP,,30\n    TANG,,1\n  NEXT\n"
       "  DT,,0.01\n  LOOP,,10\n    TIME\n    LOOP,,30\n      TANG,,1\n    NEXT\n  NEXT\n"
       "END\n2\n  0 0 1 1 1e6 1\n\n2\n  0 0 1 0 1e6 1e6-1\n\nSTOP\n";
  return d.str();
}

// The residuals of each iteration history in the log, in order: a step's,
// the step taken again with the line search, the rest of a step after a
// hinge event (its step number the next).
std::vector<std::vector<double>> stepResiduals(const std::string& log) {
  std::vector<std::vector<double>> steps;
  const std::regex line(R"(TANG\s+step\s+(\d+)\s.*\bit\s+(\d+)\s+\|R\| =\s+(\S+))");
  std::istringstream in(log);
  std::string l;
  int step = -1;
  while (std::getline(in, l)) {
    std::smatch m;
    if (!std::regex_search(l, m, line)) continue;
    if (std::stoi(m[2]) == 1 || std::stoi(m[1]) != step) steps.emplace_back();
    step = std::stoi(m[1]);
    if (!steps.empty()) steps.back().push_back(std::stod(m[3]));
  }
  return steps;
}

TEST(RcTension, MembersInTensionBendWithNewtonConvergingQuadratically) {
  const double nt = 4 * M_PI * 0.01 * 0.01 * 550e3;
  testing::DeckTempDir dir;
  int quadraticPairs = 0;
  for (const char* kin : {"SMALl", "FINIte"}) {
    for (double share : {0.0, 0.25, 0.5, 0.75, 0.95}) {
      const double n = share * nt;
      SCOPED_TRACE(std::string(kin) + " N = " + std::to_string(n));
      const testing::DeckResult r = testing::runDeckText(dir, "tension.inp", cantilever(kin, n));
      ASSERT_EQ(r.outcome.exitCode, kExitOk) << r.console << r.log.substr(r.log.size() > 3000 ? r.log.size() - 3000 : 0);
      const auto steps = stepResiduals(r.log);
      ASSERT_GE(steps.size(), 11u);
      EXPECT_EQ(r.outcome.total.hinges, 1);  // pushed past Mu(N)
      EXPECT_EQ(r.outcome.total.cuts, 0);
      for (std::size_t s = 1; s < steps.size(); ++s) {
        const std::vector<double>& res = steps[s];
        double ref = 0;
        for (std::size_t k = 1; k < res.size(); ++k) ref = std::max(ref, res[k]);
        // Only the histories that converged (not a first try given up for
        // the line search, nor a part ended by a hinge event).
        if (!(res.back() <= 1e-5 * ref)) continue;
        for (std::size_t k = 1; k + 1 < res.size(); ++k) {
          const double a = res[k] / ref, b = res[k + 1] / ref;
          if (!(a < 1e-2 && a > 1e-12)) continue;
          ++quadraticPairs;
          EXPECT_LE(b, 10 * a * a) << "step " << s + 1 << " iteration " << k + 2;
        }
      }
    }
  }
  EXPECT_GE(quadraticPairs, 5);
}

}  // namespace
}  // namespace c2d
