#include "materials/LinearSoftening.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace c2d {

LinearSoftening::LinearSoftening(double Mu, double Ks) : Mu_(Mu), Ks_(Ks) {
  if (!(Mu > 0)) throw std::invalid_argument("ultimate moment Mu must be positive");
  if (!(Ks < 0)) throw std::invalid_argument("softening modulus Ks must be negative");
}

double LinearSoftening::capacity(double xi) const { return std::max(Mu_ + Ks_ * xi, 0.0); }

Status LinearSoftening::returnMap(const SofteningState& committed, double trialMoment, double k,
                                  SofteningResponse& out) const {
  constexpr double kCapacityTol = 1e-8;
  out = SofteningResponse{};
  out.state = committed;
  const double cap = capacity(committed.xi);
  if (cap > 0 && !(k + Ks_ > 0))
    return Status::failure("softening hinge: bulk stiffness k = " + std::to_string(k) +
                           " does not exceed |Ks| = " + std::to_string(-Ks_));
  const double mag = std::abs(trialMoment);
  if (cap > 0 && mag < cap * (1 - kCapacityTol)) {  // rigid hinge: the jump does not change
    out.t = trialMoment;
    out.tangent = 1;
    return Status::success();
  }
  // Loading: |t| = |trialMoment| - k*dg = C(xi_n + dg). C is linear down to zero
  // at failureJump(), then zero; g(dg) = |trial| - k*dg - C decreases strictly
  // (k + Ks > 0), so the root is unique.
  const double sign = trialMoment >= 0 ? 1.0 : -1.0;
  double dg = -1;
  if (cap > 0) {
    dg = std::max(0.0, (mag - cap) / (k + Ks_));
    if (committed.xi + dg < failureJump()) {
      // Equal to sign*C(xi_n + dg); written as the spring's moment so that a zero
      // increment inside the round-off band returns the trial moment itself.
      out.t = trialMoment - sign * k * dg;
      out.tangent = Ks_ / (k + Ks_);
    } else {
      dg = -1;  // past complete failure
    }
  }
  if (dg < 0) {  // free hinge: the jump takes all the rotation, t = 0
    dg = mag / k;
    out.t = 0;
    out.tangent = 0;
    out.failed = true;
  }
  out.state.alpha = committed.alpha + sign * dg;
  out.state.xi = committed.xi + dg;
  out.loading = dg > 0;
  return Status::success();
}

}  // namespace c2d
