#include "materials/AxialCapacity.h"

#include <algorithm>
#include <stdexcept>

namespace c2d {

namespace {
constexpr double kYieldTol = 1e-12;  // relative round-off band of the yield conditions
// Strains within this of zero are the unloaded state's round-off: the strain
// of a member whose nodes are not exactly aligned with an axis comes out of
// its positions as +-1e-16 at rest. (1e-12 caught the vibrating free pieces
// of decks/rc/catenary.inp too, whose Newton iterations then crept at a
// twelfth of the tension branch's slope.)
constexpr double kUnloadedStrain = 1e-14;
}  // namespace

AxialCapacity::AxialCapacity(double EAc, double EAt, double Nt, double Ntu, double Nc, double eu)
    : eac_(EAc), eat_(EAt), nt_(Nt), ntu_(Ntu), nc_(Nc), eu_(eu), ht_(0) {
  if (!(EAc > 0) || !(EAt > 0) || !(Nt > 0) || !(Nc > 0))
    throw std::invalid_argument("axial capacity: EA, Nt, Nc must be positive");
  if (!(Ntu >= Nt)) throw std::invalid_argument("axial capacity: Ntu must not be below Nt");
  if (!(eu > Ntu / EAt)) throw std::invalid_argument("axial capacity: eu must exceed Ntu/(Es As)");
  ht_ = (Ntu - Nt) / (eu - Ntu / EAt);
}

AxialResponse AxialCapacity::returnMap(const AxialState& committed, double eps) const {
  AxialResponse r;
  r.state = committed;
  // At e = 0 the stiffer (compression) branch: a Newton iterate from the
  // unloaded state then falls short of the solution on either side instead of
  // overshooting a compressed member 30 times into its squash load. The
  // tangent so within round-off of e = 0 (the force is the branch's of the
  // sign of e): a member at rest whose strain came out +1e-16 took the
  // tension branch's tangent, and a frame whose nodes were moved by 1e-6 m
  // (JITTer) overshot its gravity step into divergence.
  const double e = eps - committed.ep;
  const double ea = e <= 0 ? eac_ : eat_;
  const double elasticTangent = e <= kUnloadedStrain ? eac_ : ea;
  const double nTrial = ea * e;
  const double nt = nt_ + ht_ * committed.xi;
  if (nTrial > nt * (1 + kYieldTol)) {  // bars yielding in tension
    const double dg = (nTrial - nt) / (eat_ + ht_);
    r.state.ep += dg;
    r.state.xi += dg;
    r.N = nTrial - eat_ * dg;
    r.tangent = eat_ * ht_ / (eat_ + ht_);
    r.plastic = true;
  } else if (nTrial < -nc_ * (1 + kYieldTol)) {  // crushing at the squash load
    r.state.ep += (nTrial + nc_) / eac_;
    r.N = -nc_;
    r.tangent = 0;
    r.plastic = true;
  } else {
    r.N = nTrial;
    r.tangent = elasticTangent;
  }
  return r;
}

AxialCapacity::MidPoint AxialCapacity::midPoint(double N0, double N1, double eps0, double eps1,
                                                double kt1, double dEp, double w,
                                                double ratioBound) const {
  MidPoint out;
  const double dN = N1 - N0, dE = eps1 - eps0;
  if (dEp != 0 && dE != 0) {
    const double r = std::clamp(1 - dEp / dE, -ratioBound, ratioBound);
    const double ea = stiffness(N1);
    out.n = N1 - (1 - w) * r * dN;
    out.tangent = kt1 - (1 - w) * (2 * r * kt1 - ea * r * r);
    return out;
  }
  if ((N0 < 0) == (N1 < 0) || dE == 0) {  // one elastic branch: the weighted force
    out.n = N1 - (1 - w) * dN;
    out.tangent = w * kt1;
    return out;
  }
  const double dg = (energyDensity(N1) - energyDensity(N0)) / dE;
  out.n = dg + (w - 0.5) * dN;
  out.tangent = (N1 - dg) / dE + (w - 0.5) * kt1;
  return out;
}

}  // namespace c2d
