#include "materials/EndHinge.h"

#include <stdexcept>

namespace c2d {

EndHinge::EndHinge(std::shared_ptr<const MomentCapacity> capacity, int sign, double Mu, double xiF,
                   double Mr)
    : capacity_(std::move(capacity)), sign_(sign > 0 ? 1 : -1), mu_(Mu), xiF_(xiF), mr_(Mr),
      xiEnd_(xiF * (1 - Mr / Mu)) {
  if (!(Mu > 0)) throw std::invalid_argument("end hinge: Mu must be positive");
  if (!(xiF > 0)) throw std::invalid_argument("end hinge: the failure jump must be positive");
  if (!(Mr >= 0 && Mr < Mu)) throw std::invalid_argument("end hinge: Mr must lie in [0, Mu)");
}

EndHinge::Value EndHinge::capacity(double xi, double N) const {
  Value v;
  if (xi >= xiEnd_) return v;
  double mu = mu_, dmu = 0;
  if (capacity_) {
    const MomentLaw l = capacity_->at(sign_, N);
    mu = l.Mu;
    dmu = l.dMu;
  }
  const double share = 1 - xi / xiF_;
  v.C = mu * share;
  v.dXi = -mu / xiF_;
  v.dN = dmu * share;
  return v;
}

}  // namespace c2d
