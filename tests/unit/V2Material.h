#pragma once
// The bending law of ../shared/verification.md V2 (bilinear hardening and a
// softening hinge), shared by the tests of the elements that carry it, and its
// monotonic moment-curvature relation.
#include <algorithm>
#include <optional>

#include "core/MaterialSet.h"

namespace c2d::test::v2 {

constexpr double kEI = 77650, kMc = 37.9, kMy = 268, kKh1 = 29400, kKh2 = 272;
constexpr double kMu = 274, kKs = -18000;

// A FRAMe set with resultant stiffnesses EA = 3.6e6, GA, EI and the V2 laws
// (ultimate moment Mu).
inline MaterialSet material(int number, double GA, Kinematics kinematics = Kinematics::Small,
                            double Mu = kMu, double EI = kEI) {
  MaterialSet m;
  m.number = number;
  m.elementType = "FRAMe";
  m.kinematics = kinematics;
  m.resEA = 3.6e6;
  m.resGA = GA;
  m.resEI = EI;
  m.hardening = HardeningData{kMc, kMy, kKh1, kKh2};
  m.softening = SofteningData{Mu, kKs, std::nullopt};
  return m;
}

// Curvature of the monotonic moment-curvature law at moment M >= 0.
inline double kappaOf(double M) {
  double k = M / kEI;
  if (M > kMc) k += (std::min(M, kMy) - kMc) / kKh1;
  if (M > kMy) k += (M - kMy) / kKh2;
  return k;
}

}  // namespace c2d::test::v2
