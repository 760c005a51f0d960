#include "materials/HingedBending.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/io/Checkpoint.h"

namespace c2d {

namespace {

BilinearHardening makeBending(const MaterialSet& mat, int index) {
  if (!mat.hardening) return BilinearHardening::elastic(mat.EI());
  const HardeningValues& h =
      index == 1 && mat.hardening->negative ? *mat.hardening->negative : *mat.hardening;
  return {mat.EI(), h.Mc, h.My, h.Kh1, h.Kh2};
}

std::optional<LinearSoftening> makeSoftening(const MaterialSet& mat, int index) {
  if (!mat.softening) return std::nullopt;
  if (index == 1 && mat.softening->negative)
    return LinearSoftening(mat.softening->negative->first, mat.softening->negative->second);
  return LinearSoftening(mat.softening->Mu, mat.softening->Ks);
}

double signOf(double x) { return x < 0 ? -1.0 : 1.0; }

}  // namespace

HingedBending::HingedBending(const MaterialSet& mat)
    : bending_{makeBending(mat, 0), makeBending(mat, 1)},
      softening_{makeSoftening(mat, 0), makeSoftening(mat, 1)},
      capacity_(mat.capacity),
      site_(mat.softening ? mat.hingeSite : HingeSite::Midpoint) {}

double HingedBending::ultimate(int sign, double N) const {
  const int i = sign > 0 ? 0 : 1;
  if (!softening_[i]) return 0;
  return capacity_ ? capacity_->at(sign, N).Mu : softening_[i]->Mu();
}

LinearSoftening HingedBending::softeningAt(int sign, double N, double* dMu) const {
  const LinearSoftening& given = *softening_[sign > 0 ? 0 : 1];
  if (dMu) *dMu = 0;
  if (!capacity_) return given;
  // Ks(N) = -Mu(N)/xiF: the failure jump of the law as given.
  const MomentLaw l = capacity_->at(sign, N);
  if (dMu) *dMu = l.dMu;
  return LinearSoftening(l.Mu, -l.Mu / given.failureJump());
}

BendingResponse HingedBending::bulk(const BendingState& from, double kappa, double N,
                                    double& dMdN) const {
  dMdN = 0;
  const int i = bending_[0].EI() * (kappa - from.kp) < 0 ? 1 : 0;
  if (!capacity_ || bending_[i].isElastic()) return bending_[i].returnMap(from, kappa);
  const double EI = bending_[0].EI();
  const MomentLaw l = capacity_->at(i == 0 ? 1 : -1, N);
  const BilinearHardening law(EI, l.Mc, l.My, l.Kh1, l.Kh2);
  BendingResponse r = law.returnMap(from, kappa);
  if (r.plastic) {
    // |M| = R(xi, N) on the yield surface: dM/dN = sign EI R_N / (EI + R_xi).
    const double xi = r.state.xi;
    double rN = l.dMc + l.dKh1 * xi, kh = l.Kh1;
    if (r.secondBranch) {
      const double xiY = l.Kh1 > 0 ? (l.My - l.Mc) / l.Kh1 : 0.0;
      const double dxiY = l.Kh1 > 0 ? ((l.dMy - l.dMc) - xiY * l.dKh1) / l.Kh1 : 0.0;
      rN = l.dMy + l.dKh2 * (xi - xiY) - l.Kh2 * dxiY;
      kh = l.Kh2;
    }
    dMdN = (i == 0 ? 1.0 : -1.0) * rN * EI / (EI + kh);
  }
  return r;
}

Status HingedBending::respond(double kappaD, double l, const HingedBendingState& from,
                              double openSign, HingedBendingResponse& out, double N,
                              bool held) const {
  const double EI = bending_[0].EI();
  HingedBendingState& to = out.state;
  to = from;
  to.N = N;
  out.dN = 0;
  const bool opens = openSign != 0 && site_ == HingeSite::Midpoint && softening_[0];
  if (!from.hingeActive && !opens) {
    const BendingResponse r = bulk(from.bulk, kappaD, N, out.dN);
    to.M = r.M;
    to.bulk = r.state;
    to.hingeFailed = false;
    out.tangent = r.tangent;
    if (held && softening_[0] && site_ == HingeSite::Midpoint) holdAtUltimate(kappaD, out);
    return std::isfinite(to.M) ? Status::success()
                               : Status::failure("bending section: non-finite moment");
  }
  // Bulk elastic with frozen plastic curvature (eq 33); kappa = kappaD - alpha/l.
  const double k = EI / l;  // condensation term EI*Gbar^2*l
  const double sign = from.hingeActive ? from.hingeSign : (openSign > 0 ? 1.0 : -1.0);
  double dMu = 0;
  const LinearSoftening law = softeningAt(sign > 0 ? 1 : -1, N, &dMu);
  if (law.capacity(from.jump.xi) > 0 && !(k + law.Ks() > 0)) {
    std::ostringstream msg;
    msg << "softening hinge: element length l_e = " << l << " must be below EI/|Ks| = "
        << EI / -law.Ks() << " (K_alpha_alpha = EI/l_e + Ks = " << k + law.Ks()
        << " is not positive); refine the mesh";
    return Status::failure(msg.str());
  }
  if (!from.hingeActive) {
    to.hingeActive = true;
    to.hingeSign = sign;
    const int s = sign > 0 ? 1 : -1;
    double xiU = bending_[s > 0 ? 0 : 1].hardeningAt(law.Mu());
    if (capacity_ && !bending_[0].isElastic()) {
      const MomentLaw b = capacity_->at(s, N);
      xiU = BilinearHardening(EI, b.Mc, b.My, b.Kh1, b.Kh2).hardeningAt(law.Mu());
    }
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
  if (capacity_ && !r.failed && r.tangent != 1.0) {
    // Softening: |t| = Mu(N) (1 - xi/xiF), xiF fixed: dt/dN = sign Mu'(N)(1 - xi/xiF) k/(k + Ks).
    const double cN = dMu * (1 - r.state.xi / law.failureJump());
    out.dN = signOf(mTrial) * cN * k / (k + law.Ks());
  }
  return std::isfinite(to.M) && std::isfinite(out.tangent)
             ? Status::success()
             : Status::failure("bending section: non-finite moment");
}

void HingedBending::holdAtUltimate(double kappaD, HingedBendingResponse& out) const {
  HingedBendingState& to = out.state;
  const int sign = to.M < 0 ? -1 : 1;
  const double mu = ultimate(sign, to.N);
  if (!(std::abs(to.M) > mu)) return;
  // M = EI (kappaD - kp) = sign Mu: the plastic curvature takes the rest.
  const double kp = kappaD - sign * mu / EI();
  to.bulk.xi += std::abs(kp - to.bulk.kp);
  to.bulk.kp = kp;
  to.M = sign * mu;
  out.tangent = 0;
  out.dN = capacity_ ? sign * capacity_->at(sign, to.N).dMu : 0.0;
}

HingedBending::MidPointMoment HingedBending::midPointMoment(const HingedBendingState& from,
                                                            double kappaD0,
                                                            const HingedBendingState& to,
                                                            double kappaD1, double kt1, double l,
                                                            double w) const {
  const double dM = to.M - from.M, dK = kappaD1 - kappaD0;
  const double dKp = (to.bulk.kp - from.bulk.kp) + (to.jump.alpha - from.jump.alpha) / l;
  MidPointMoment out;
  if (!(dKp != 0 && dK != 0)) {
    out.m = to.M - (1.0 - w) * dM;
    out.tangent = w * kt1;
    out.dM1 = w;
    return out;
  }
  // A plastic step has dK != 0 (flow needs a trial moment beyond the surface);
  // r is bounded by max(1, |Ks| / (EI/l + Ks)) for laws that do not follow N.
  const double r = 1.0 - dKp / dK;
  if (capacity_ && std::abs(r) > kMidPointRatio) {
    const double rc = std::clamp(r, -kMidPointRatio, kMidPointRatio);
    out.m = to.M - (1.0 - w) * rc * dM;
    out.tangent = kt1 * (1.0 - (1.0 - w) * rc);
    out.dM1 = 1.0 - (1.0 - w) * rc;
    return out;
  }
  out.m = to.M - (1.0 - w) * r * dM;
  // d(r dM)/dK1 = d(dM^2/(EI dK))/dK1 = 2 r kt1 - EI r^2.
  out.tangent = kt1 - (1.0 - w) * (2.0 * r * kt1 - EI() * r * r);
  out.dM1 = 1.0 - 2.0 * (1.0 - w) * r;
  return out;
}

bool HingedBending::canActivate(const HingedBendingState& s) const {
  if (!softening_[0]) return false;
  if (site_ == HingeSite::Midpoint) return !s.hingeActive;
  return s.endHinge[0] == 0 || s.endHinge[1] == 0;
}

namespace {

// Demand of each end of a state (0 for an end whose hinge has opened).
std::array<double, 2> endDemands(const HingedBending& law, const HingedBendingState& s) {
  std::array<double, 2> d{0, 0};
  for (int a = 0; a < 2; ++a)
    if (s.endHinge[a] == 0) {
      const double mu = law.ultimate(s.endMoment[a] < 0 ? -1 : 1, s.N);
      if (mu > 0) d[a] = std::abs(s.endMoment[a]) / mu;
    }
  return d;
}

}  // namespace

HingeInfo HingedBending::info(const HingedBendingState& s) const {
  HingeInfo h;
  if (site_ == HingeSite::Ends) {
    // The hinges are joints (elements/JointedElement): this reports the end
    // that could open next, its moment and capacity.
    const std::array<double, 2> d = endDemands(*this, s);
    int a = d[1] > d[0] ? 1 : 0;
    for (int b = 0; b < 2; ++b)
      if (std::abs(s.endHinge[b]) == 1) a = b;  // the end just opened
    for (double e : s.endHinge) {
      h.count += e != 0;
      h.jointDue = h.jointDue || std::abs(e) == 1;
    }
    h.position = a;
    h.moment = s.endMoment[a];
    // An end whose hinge is a joint carries the joint's moment plus the end
    // section's inertia: the joint reports its own (JointedElement::hingeInfo).
    if (s.endHinge[a] == 0) h.ultimate = ultimate(s.endMoment[a] < 0 ? -1 : 1, s.N);
    return h;
  }
  h.active = s.hingeActive;
  h.failed = s.hingeFailed;
  h.position = 0.5;
  h.jump = s.jump.alpha;
  h.moment = s.M;
  h.softening = s.jump.xi;
  if (softening_[0])
    h.ultimate = ultimate(static_cast<int>(s.hingeActive ? s.hingeSign : signOf(s.M)), s.N);
  return h;
}

void HingedBending::open(HingedBendingState& s) const {
  if (!canActivate(s)) return;
  if (site_ == HingeSite::Ends) {
    const std::array<double, 2> d = endDemands(*this, s);
    const int a = d[1] > d[0] ? 1 : 0;
    s.endHinge[a] = signOf(s.endMoment[a]);
    return;
  }
  s.hingeActive = true;
  s.hingeSign = s.M >= 0 ? 1.0 : -1.0;
}

int HingedBending::criticalEnd(const HingedBendingState& s) const {
  if (site_ != HingeSite::Ends || !canActivate(s)) return -1;
  const std::array<double, 2> d = endDemands(*this, s);
  const int a = d[1] > d[0] ? 1 : 0;
  return d[a] > 0 ? a : -1;
}

void HingedBending::openEnd(HingedBendingState& s, int end) const {
  if (site_ != HingeSite::Ends || end < 0 || end > 1 || s.endHinge[end] != 0) return;
  s.endHinge[end] = signOf(s.endMoment[end]);
}

double HingedBending::demand(const HingedBendingState& s) const {
  if (!canActivate(s)) return 0;
  if (site_ == HingeSite::Ends) {
    const std::array<double, 2> d = endDemands(*this, s);
    return std::max(d[0], d[1]);
  }
  return std::abs(s.M) / ultimate(s.M < 0 ? -1 : 1, s.N);
}

// A field added to the history must be added to the restart file too.
static_assert(sizeof(HingedBendingState) == 12 * sizeof(double),
              "restart files: putSection/getSection write every history field");

void putSection(std::ostream& out, const HingedBendingState& s) {
  using namespace checkpoint;
  for (double x : {s.bulk.kp, s.bulk.xi, s.jump.alpha, s.jump.xi, s.hingeSign, s.M, s.N,
                   s.endMoment[0], s.endMoment[1], s.endHinge[0], s.endHinge[1]})
    put(out, x);
  for (bool b : {s.hingeActive, s.hingeFailed}) putBool(out, b);
}

HingedBendingState getSection(std::istream& in) {
  using namespace checkpoint;
  HingedBendingState s;
  for (double* x : {&s.bulk.kp, &s.bulk.xi, &s.jump.alpha, &s.jump.xi, &s.hingeSign, &s.M, &s.N,
                    &s.endMoment[0], &s.endMoment[1], &s.endHinge[0], &s.endHinge[1]})
    *x = get<double>(in);
  s.hingeActive = getBool(in);
  s.hingeFailed = getBool(in);
  return s;
}

}  // namespace c2d
