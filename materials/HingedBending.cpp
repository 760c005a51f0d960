#include "materials/HingedBending.h"

#include <cmath>
#include <sstream>

#include "core/Checkpoint.h"

namespace c2d {

namespace {

BilinearHardening makeBending(const MaterialSet& mat) {
  if (!mat.hardening) return BilinearHardening::elastic(mat.EI());
  const HardeningData& h = *mat.hardening;
  return {mat.EI(), h.Mc, h.My, h.Kh1, h.Kh2};
}

std::optional<LinearSoftening> makeSoftening(const MaterialSet& mat) {
  if (!mat.softening) return std::nullopt;
  return LinearSoftening(mat.softening->Mu, mat.softening->Ks);
}

}  // namespace

HingedBending::HingedBending(const MaterialSet& mat)
    : bending_(makeBending(mat)), softening_(makeSoftening(mat)) {}

Status HingedBending::respond(double kappaD, double l, const HingedBendingState& from,
                              double openSign, HingedBendingResponse& out) const {
  const double EI = bending_.EI();
  HingedBendingState& to = out.state;
  to = from;
  if (!from.hingeActive && (openSign == 0 || !canActivate(from))) {
    const BendingResponse r = bending_.returnMap(from.bulk, kappaD);
    to.M = r.M;
    to.bulk = r.state;
    to.hingeFailed = false;
    out.tangent = r.tangent;
    return std::isfinite(to.M) ? Status::success()
                               : Status::failure("bending section: non-finite moment");
  }
  // Bulk elastic with frozen plastic curvature (eq 33); kappa = kappaD - alpha/l.
  const double k = EI / l;  // condensation term EI*Gbar^2*l
  const LinearSoftening& law = *softening_;
  if (law.capacity(from.jump.xi) > 0 && !(k + law.Ks() > 0)) {
    std::ostringstream msg;
    msg << "softening hinge: element length l_e = " << l << " must be below EI/|Ks| = "
        << EI / -law.Ks() << " (K_alpha_alpha = EI/l_e + Ks = " << k + law.Ks()
        << " is not positive); refine the mesh";
    return Status::failure(msg.str());
  }
  if (!from.hingeActive) {
    to.hingeActive = true;
    to.hingeSign = openSign > 0 ? 1.0 : -1.0;
    const double xiU = bending_.hardeningAt(law.Mu());
    if (std::isfinite(xiU) && xiU > to.bulk.xi) {
      to.bulk.kp += to.hingeSign * (xiU - to.bulk.xi);
      to.bulk.xi = xiU;
    }
  }
  const double mTrial = EI * (kappaD - from.jump.alpha / l - to.bulk.kp);
  SofteningResponse r;
  if (Status st = law.returnMap(from.jump, mTrial, k, r); !st) return st;
  to.M = r.t;  // hinge equation h = -M + t = 0
  to.jump = r.state;
  to.hingeFailed = r.failed;
  out.tangent = EI * r.tangent;
  return std::isfinite(to.M) && std::isfinite(out.tangent)
             ? Status::success()
             : Status::failure("bending section: non-finite moment");
}

HingedBending::MidPointMoment HingedBending::midPointMoment(const HingedBendingState& from,
                                                            double kappaD0,
                                                            const HingedBendingState& to,
                                                            double kappaD1, double kt1, double l,
                                                            double w) const {
  const double dM = to.M - from.M, dK = kappaD1 - kappaD0;
  const double dKp = (to.bulk.kp - from.bulk.kp) + (to.jump.alpha - from.jump.alpha) / l;
  // A plastic step has dK != 0 (flow needs a trial moment beyond the surface);
  // r is bounded by max(1, |Ks| / (EI/l + Ks)).
  const double r = dKp != 0 && dK != 0 ? 1.0 - dKp / dK : 1.0;
  MidPointMoment out;
  out.m = to.M - (1.0 - w) * r * dM;
  // d(r dM)/dK1 = d(dM^2/(EI dK))/dK1 = 2 r kt1 - EI r^2.
  out.tangent = dKp != 0 && dK != 0 ? kt1 - (1.0 - w) * (2.0 * r * kt1 - EI() * r * r) : w * kt1;
  return out;
}

HingeInfo HingedBending::info(const HingedBendingState& s) const {
  HingeInfo h;
  h.active = s.hingeActive;
  h.failed = s.hingeFailed;
  h.position = 0.5;
  h.jump = s.jump.alpha;
  h.moment = s.M;
  h.softening = s.jump.xi;
  if (softening_) h.ultimate = softening_->Mu();
  return h;
}

void HingedBending::open(HingedBendingState& s) const {
  if (!canActivate(s)) return;
  s.hingeActive = true;
  s.hingeSign = s.M >= 0 ? 1.0 : -1.0;
}

double HingedBending::demand(const HingedBendingState& s) const {
  if (!canActivate(s)) return 0;
  return std::abs(s.M) / softening_->Mu();
}

// A field added to the history must be added to the restart file too.
static_assert(sizeof(HingedBendingState) == 7 * sizeof(double),
              "restart files: putSection/getSection write every history field");

void putSection(std::ostream& out, const HingedBendingState& s) {
  using namespace checkpoint;
  for (double x : {s.bulk.kp, s.bulk.xi, s.jump.alpha, s.jump.xi, s.hingeSign, s.M}) put(out, x);
  for (bool b : {s.hingeActive, s.hingeFailed}) putBool(out, b);
}

HingedBendingState getSection(std::istream& in) {
  using namespace checkpoint;
  HingedBendingState s;
  for (double* x : {&s.bulk.kp, &s.bulk.xi, &s.jump.alpha, &s.jump.xi, &s.hingeSign, &s.M})
    *x = get<double>(in);
  s.hingeActive = getBool(in);
  s.hingeFailed = getBool(in);
  return s;
}

}  // namespace c2d
