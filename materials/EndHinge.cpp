#include "materials/EndHinge.h"

#include <stdexcept>

namespace c2d {

EndHinge::EndHinge(std::shared_ptr<const MomentCapacity> capacity, int sign, double Mu, double xiF)
    : capacity_(std::move(capacity)), sign_(sign > 0 ? 1 : -1), mu_(Mu), xiF_(xiF) {
  if (!(Mu > 0)) throw std::invalid_argument("end hinge: Mu must be positive");
  if (!(xiF > 0)) throw std::invalid_argument("end hinge: the failure jump must be positive");
}

EndHinge::Value EndHinge::capacity(double xi, double N) const {
  Value v;
  if (xi >= xiF_) return v;
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
