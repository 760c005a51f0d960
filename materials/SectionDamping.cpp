#include "materials/SectionDamping.h"

namespace c2d {

SectionDamping::Bending SectionDamping::bending(double f, double EI, double dM, double dK,
                                                double kt1) {
  if (f == 0) return {};
  // No curvature change: an elastic step's limit (m = 0, slope f EI s^2 with s
  // = 1); a plastic step always changes the curvature.
  if (dK == 0) return {0, dM == 0 ? f * EI : 0, 0};
  const double r = dM / (EI * dK);
  if (r <= 0) return {};
  if (r >= 1) return elasticBending(f, EI, dK);
  // m = f r dM = f dM^2/(EI dK); d(dM^2/(EI dK))/dK1 = 2 r kt1 - EI r^2.
  return {f * r * dM, f * (2 * r * kt1 - EI * r * r), 2 * f * r};
}

}  // namespace c2d
