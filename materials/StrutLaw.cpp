#include "materials/StrutLaw.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace c2d {

StrutLaw::StrutLaw(double K, double Pu) : K_(K), Pu_(Pu) {
  if (!(K > 0) || !(Pu > 0) || !std::isfinite(K) || !std::isfinite(Pu))
    throw std::invalid_argument("an infill strut needs a positive stiffness and strength");
}

void StrutLaw::scale(double f) {
  if (!(f > 0) || f > 1) throw std::invalid_argument("a strut keeps a share in (0, 1]");
  K_ *= f;
  Pu_ *= f;
}

double StrutLaw::envelope(double s, double* slope) const {
  const double sp = peakStrain();
  const std::array<double, 5> xs{0, sp, kResidualStart * sp, kResidualEnd * sp, kGone * sp};
  const std::array<double, 5> ps{0, Pu_, kResidual * Pu_, kResidual * Pu_, 0};
  if (slope) *slope = 0;
  if (s <= 0 || s >= xs.back()) return 0;
  std::size_t k = 1;
  while (s > xs[k]) ++k;
  const double m = (ps[k] - ps[k - 1]) / (xs[k] - xs[k - 1]);
  if (slope) *slope = m;
  return ps[k - 1] + m * (s - xs[k - 1]);
}

StrutResponse StrutLaw::evaluate(double eps, const StrutLawState& committed) const {
  StrutResponse out;
  out.state = committed;
  const double s = -eps;
  if (committed.gone) return out;
  if (committed.doomed && s <= 0) {  // its panel crushed: goes once unloaded
    out.state.gone = true;
    return out;
  }
  if (s >= kGone * peakStrain()) {
    out.state.kappa = s;
    out.state.gone = true;
    return out;
  }
  if (s <= 0) return out;  // tension: nothing
  double P = 0, dP = 0;
  if (s >= committed.kappa) {  // on the envelope
    P = envelope(s, &dP);
    out.state.kappa = std::max(committed.kappa, s);
  } else {  // inside: the secant through the largest shortening
    const double secant = envelope(committed.kappa) / committed.kappa;
    P = secant * s;
    dP = secant;
  }
  out.N = -P;
  out.dN = dP;  // dN/deps = dP/ds
  out.energy = 0.5 * P * s;
  return out;
}

}  // namespace c2d
