#include "materials/AxialCapacity.h"

#include <stdexcept>

namespace c2d {

namespace {
constexpr double kYieldTol = 1e-12;  // relative round-off band of the yield conditions
}

AxialCapacity::AxialCapacity(double EA, double Nt, double Ntu, double Nc, double eu)
    : ea_(EA), nt_(Nt), ntu_(Ntu), nc_(Nc), eu_(eu), ht_(0) {
  if (!(EA > 0) || !(Nt > 0) || !(Nc > 0)) throw std::invalid_argument("axial capacity: EA, Nt, Nc must be positive");
  if (!(Ntu >= Nt)) throw std::invalid_argument("axial capacity: Ntu must not be below Nt");
  if (!(eu > Ntu / EA)) throw std::invalid_argument("axial capacity: eu must exceed Ntu/EA");
  ht_ = (Ntu - Nt) / (eu - Ntu / EA);
}

AxialResponse AxialCapacity::returnMap(const AxialState& committed, double eps) const {
  AxialResponse r;
  r.state = committed;
  const double nTrial = ea_ * (eps - committed.ep);
  const double nt = nt_ + ht_ * committed.xi;
  if (nTrial > nt * (1 + kYieldTol)) {  // bars yielding in tension
    const double dg = (nTrial - nt) / (ea_ + ht_);
    r.state.ep += dg;
    r.state.xi += dg;
    r.N = nTrial - ea_ * dg;
    r.tangent = ea_ * ht_ / (ea_ + ht_);
    r.plastic = true;
  } else if (nTrial < -nc_ * (1 + kYieldTol)) {  // crushing at the squash load
    r.state.ep += (nTrial + nc_) / ea_;
    r.N = -nc_;
    r.tangent = 0;
    r.plastic = true;
  } else {
    r.N = nTrial;
    r.tangent = ea_;
  }
  return r;
}

}  // namespace c2d
