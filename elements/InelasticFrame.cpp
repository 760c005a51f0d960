#include "elements/InelasticFrame.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "materials/RcSection.h"

namespace c2d {

namespace {


// Strain-displacement rows at the midpoint, element frame, dof order
// (u1, v1, theta1, u2, v2, theta2).
struct Rows {
  ElemVec eps, gamma, kappa;
};

Rows midpointRows(double l) {
  Rows b;
  b.eps << -1 / l, 0, 0, 1 / l, 0, 0;
  b.gamma << 0, -1 / l, -0.5, 0, 1 / l, -0.5;
  b.kappa << 0, 0, -1 / l, 0, 0, 1 / l;
  return b;
}

}  // namespace

InelasticFrame::InelasticFrame(const MaterialSet& mat, const std::array<int, 2>& nodes,
                               const Vec2& x1, const Vec2& x2,
                               const std::array<double, 2>& offsets)
    : nodes_(nodes),
      material_(mat.number),
      length_((x2 - x1).norm() - offsets[0] - offsets[1]),
      EA_(mat.EA()),
      GA_(mat.GA()),
      rhoA_(mat.rhoA()),
      law_(mat),
      damping_(mat.dampingA1) {
  if (mat.rc) axial_ = mat.rc->axialCapacity();
  rc_ = mat.rc;
  const double full = (x2 - x1).norm();
  if (!(full > 0)) throw std::invalid_argument("frame element with coincident nodes");
  rigid_ = RigidEnds(x1, x2, offsets[0], offsets[1]);
  if (!(EA_ > 0) || !(GA_ > 0))
    throw std::invalid_argument("frame element needs positive EA and GA");
  const double c = (x2.x() - x1.x()) / full, s = (x2.y() - x1.y()) / full;
  rotation_.setZero();
  for (int n = 0; n < 2; ++n) {
    const int o = kNodeDofs * n;
    rotation_(o, o) = c;
    rotation_(o, o + 1) = s;
    rotation_(o + 1, o) = -s;
    rotation_(o + 1, o + 1) = c;
    rotation_(o + 2, o + 2) = 1;
  }
  toLocal_ = rotation_ * rigid_.linearMap();

  // Translational mass is isotropic, so the same matrix holds in the global
  // frame; the rigid zones' mass belongs to the joint region: the full length's.
  mass_.setZero();
  const double mA = mat.rhoA() * full, mI = mat.rhoI() * full;
  for (int dof = 0; dof < kNodeDofs; ++dof) {
    const double m = dof == 2 ? mI : mA;
    const int a = dof, b = kNodeDofs + dof;
    if (mat.mass == MassType::Lumped) {
      mass_(a, a) = mass_(b, b) = m / 2;
    } else {
      mass_(a, a) = mass_(b, b) = m / 3;
      mass_(a, b) = mass_(b, a) = m / 6;
    }
  }
}

// The stress resultants of the step's scheme and the section dashpot.
struct InelasticFrame::Resultants {
  double w = 1, f = 0;   // the scheme's weight of t_n+1, the dashpot's factor
  double N = 0, kN = 0;  // the axial resultant of the scheme and dN/deps
  double V = 0, M = 0;
  SectionDamping::Bending md;  // the dashpot's bending part
};

Status InelasticFrame::trialSection(const ElemVec& dl, HingedBendingResponse& bend) {
  const double l = length_;
  const Rows b = midpointRows(l);
  const HingedBendingState& from = committed_.section;
  const double openSign =
      !from.hingeActive && trial_.section.hingeActive ? trial_.section.hingeSign : 0.0;
  // The axial force first: the bending laws follow it.
  const double eps = b.eps.dot(dl);
  double N1 = EA_ * eps;
  axialTangent_ = EA_;
  if (axial_) {
    const AxialResponse a = axial_->returnMap(committed_.axial, eps);
    N1 = a.N;
    axialTangent_ = a.tangent;
    trial_.axial = a.state;
  }
  const std::array<double, 2> ends = trial_.section.endHinge;  // opened in this trial
  if (Status st = law_.respond(b.kappa.dot(dl), l, from, openSign, bend, N1); !st) return st;
  trial_.section = bend.state;
  for (int a = 0; a < 2; ++a)
    if (from.endHinge[a] == 0) trial_.section.endHinge[a] = ends[a];
  trial_.forces = {N1, GA_ * b.gamma.dot(dl), bend.state.M};
  // End moments from the element's equilibrium (section sign convention).
  trial_.section.endMoment = {trial_.forces.M + 0.5 * l * trial_.forces.V,
                              trial_.forces.M - 0.5 * l * trial_.forces.V};
  if (!std::isfinite(trial_.forces.N) || !std::isfinite(trial_.forces.V))
    return Status::failure("inelastic frame: non-finite section forces");
  return Status::success();
}

InelasticFrame::Resultants InelasticFrame::schemeResultants(
    const ElemVec& dl, const ElemVec& dln, const StepRule& rule,
    const HingedBendingResponse& bend) const {
  const Rows b = midpointRows(length_);
  const double eps = b.eps.dot(dl);
  const double kt = bend.tangent;
  Resultants s;
  const double w = s.w = rule.scheme == Scheme::MidPoint ? 0.5 + rule.alpha : 1.0;
  const SectionForces& f1 = trial_.forces;
  if (!axial_) {
    s.N = w * f1.N + (1 - w) * EA_ * b.eps.dot(dln);
    s.kN = w * EA_;
  } else if (rule.scheme != Scheme::MidPoint) {
    s.N = f1.N;
    s.kN = axialTangent_;
  } else {
    const AxialCapacity::MidPoint mp =
        axial_->midPoint(committed_.forces.N, f1.N, b.eps.dot(dln), eps, axialTangent_,
                         trial_.axial.ep - committed_.axial.ep, w, HingedBending::kMidPointRatio);
    s.N = mp.n;
    s.kN = mp.tangent;
  }
  s.V = w * f1.V + (1 - w) * GA_ * b.gamma.dot(dln);
  s.M = w * f1.M + (1 - w) * committed_.forces.M;
  // The section's dashpot (materials/SectionDamping.h): f = a1/h times the
  // elastic part of the strains' change: in bending the elastic curvature's,
  // axially (a bounded axial force) the elastic strain's.
  const double f = s.f = damping_.factor(rule);
  SectionDamping::Bending nd;
  if (f > 0) {
    const ElemVec ddl = dl - dln;
    const double dE = b.eps.dot(ddl);
    if (axial_) {
      nd = axial_->damping(f, committed_.forces.N, f1.N, dE,
                           trial_.axial.ep - committed_.axial.ep, axialTangent_);
    } else {
      nd = SectionDamping::elasticBending(f, EA_, dE);
    }
    s.N += nd.m;
    s.kN += nd.tangent;
    s.V += f * GA_ * b.gamma.dot(ddl);
    const double dK = b.kappa.dot(ddl);
    s.md = law_.isElastic()
               ? SectionDamping::elasticBending(f, law_.EI(), dK)
               : SectionDamping::bending(f, law_.EI(), f1.M - committed_.forces.M, dK, kt);
    s.M += s.md.m;
  }
  return s;
}

ElemMat InelasticFrame::localTangent(const Resultants& s, const HingedBendingResponse& bend,
                                     bool coupled) const {
  const double l = length_;
  const Rows b = midpointRows(l);
  const double kt = bend.tangent, w = s.w, f = s.f;
  const SectionDamping::Bending& md = s.md;
  if (!coupled)
    return l * ((w + f) * (EA_ * b.eps * b.eps.transpose() + GA_ * b.gamma * b.gamma.transpose()) +
                (w * kt + md.tangent) * b.kappa * b.kappa.transpose());
  // The moment follows N: dM/ddl = kt b_kappa + dM/dN dN/deps b_eps.
  return l * (s.kN * b.eps * b.eps.transpose() + (w + f) * GA_ * b.gamma * b.gamma.transpose() +
              (w * kt + md.tangent) * b.kappa * b.kappa.transpose() +
              (w + md.dM1) * bend.dN * axialTangent_ * b.kappa * b.eps.transpose());
}

Status InelasticFrame::evaluate(const ElementKinematics& kin, const StepRule& rule,
                                bool wantTangent, ElemVec& residual, ElemMat& tangent) {
  const ElemVec dl = toLocal_ * kin.d - dl0_;
  HingedBendingResponse bend;
  if (Status st = trialSection(dl, bend); !st) return st;
  // The mid-point scheme takes the stress resultants between t_n and t_n+1: for
  // the elastic axial and shear parts the weighted strains, for the bending
  // moment the weighted moments of the committed and the trial state.
  const ElemVec dln = toLocal_ * kin.dn - dl0_;
  const Resultants s = schemeResultants(dl, dln, rule, bend);
  const bool coupled = axial_ || bend.dN != 0;
  const Rows b = midpointRows(length_);
  const ElemVec fLocal = length_ * (s.N * b.eps + s.V * b.gamma + s.M * b.kappa);
  residual = toLocal_.transpose() * fLocal;
  if (wantTangent) {
    const ElemMat kLocal = localTangent(s, bend, coupled);
    tangent = toLocal_.transpose() * kLocal * toLocal_;
  }
  if (rule.dynamic()) {
    const ElemVec dd = kin.d - kin.dn;
    if (!rule.rotationsInRange(dd)) return Status::failure(StepRule::kRotationRangeMessage);
    rule.pairWithRate(dd, residual, wantTangent ? &tangent : nullptr);
    rule.addInertia(mass_, dd, kin.vn, kin.an, residual, wantTangent ? &tangent : nullptr);
  }
  if (!residual.allFinite() || (wantTangent && !tangent.allFinite()))
    return Status::failure("inelastic frame: non-finite residual or tangent");
  return Status::success();
}

ElemVec InelasticFrame::bodyLoad(const Vec2& g) const {
  // Uniform weight rhoA*g: half to each node, no nodal moments (consistent for linear shape functions).
  ElemVec f = ElemVec::Zero();
  const double w = 0.5 * rhoA_ * fullLength();
  f.segment<2>(0) = w * g;
  f.segment<2>(kNodeDofs) = w * g;
  return f;
}

double InelasticFrame::strainEnergy() const {
  const SectionForces& f = trial_.forces;
  const double axial = axial_ ? 2 * axial_->energyDensity(f.N) : f.N * f.N / EA_;
  return 0.5 * length_ * (axial + f.V * f.V / GA_ + f.M * f.M / law_.EI());
}

SectionForces InelasticFrame::sectionForces() const { return trial_.forces; }

double InelasticFrame::fractureDemand() const {
  if (!axial_ || trial_.fracture != Parting::Whole) return 0;
  return axial_->fractureDemand(axial_->strain(trial_.forces.N, trial_.axial));
}

double InelasticFrame::shearDemand() const {
  if (!rc_ || trial_.fracture != Parting::Whole) return 0;
  return rc_->shear().demand(trial_.forces.V, trial_.forces.N);
}

double InelasticFrame::shearCapacity() const {
  return rc_ ? rc_->shearCapacity(trial_.forces.N) : 0.0;
}

double InelasticFrame::hingeDemand() const {
  return std::max({law_.demand(trial_.section), fractureDemand(), shearDemand()});
}

void InelasticFrame::activateHinge() {
  const double fracture = fractureDemand(), shear = shearDemand();
  if (std::max(fracture, shear) > law_.demand(trial_.section))
    trial_.fracture = shear > fracture ? Parting::Sheared : Parting::BarsFractured;
  else
    law_.open(trial_.section);
}

int InelasticFrame::earlyEnd() const {
  return law_.demand(trial_.section) >= std::max(fractureDemand(), shearDemand())
             ? law_.criticalEnd(trial_.section)
             : -1;
}

void InelasticFrame::activateHingeAt(int end) { law_.openEnd(trial_.section, end); }

HingeInfo InelasticFrame::hinge() const {
  HingeInfo h = law_.info(trial_.section);
  h.fracture =
      trial_.fracture == Parting::BarsFractured || trial_.fracture == Parting::Sheared;
  h.shear = trial_.fracture == Parting::Sheared;
  return h;
}

ElemVec InelasticFrame::axialForceGradient() const {
  return axialTangent_ * (toLocal_.transpose() * midpointRows(length_).eps);
}

// ------------------------------------------------------------ restart files

// A field added to the history must be added to the restart file too.

void InelasticFrame::writeState(std::ostream& out) const {
  using namespace checkpoint;
  for (int n : nodes_) put(out, n);
  put(out, material_);
  for (double x : {length_, EA_, GA_, rhoA_, damping_.coefficient()}) put(out, x);
  putFixed(out, rotation_);
  putFixed(out, mass_);
  for (const PointState* p : {&committed_, &trial_}) {
    putSection(out, p->section);
    for (double x : {p->forces.N, p->forces.V, p->forces.M, p->axial.ep, p->axial.xi}) put(out, x);
    put(out, static_cast<int>(p->fracture));
  }
  put(out, axialTangent_);
  putFixed(out, dl0_);
  for (double o : rigid_.offsets()) put(out, o);
}

void InelasticFrame::readState(std::istream& in) {
  using namespace checkpoint;
  for (int& n : nodes_) n = get<int>(in);
  material_ = get<int>(in);
  for (double* x : {&length_, &EA_, &GA_, &rhoA_}) *x = get<double>(in);
  damping_ = SectionDamping(get<double>(in));
  getFixed(in, rotation_);
  getFixed(in, mass_);
  for (PointState* p : {&committed_, &trial_}) {
    p->section = getSection(in);
    for (double* x : {&p->forces.N, &p->forces.V, &p->forces.M, &p->axial.ep, &p->axial.xi})
      *x = get<double>(in);
    p->fracture = getParting(in);
  }
  axialTangent_ = get<double>(in);
  getFixed(in, dl0_);
  const double o1 = get<double>(in), o2 = get<double>(in);
  rigid_ = RigidEnds(Vec2::Zero(), (length_ + o1 + o2) * Vec2(rotation_(0, 0), rotation_(0, 1)), o1,
                     o2);
  toLocal_ = rotation_ * rigid_.linearMap();
}

// ------------------------------------------------------------ material change

Status InelasticFrame::setMaterial(const MaterialSet& mat, const ElemVec& d) {
  if (mat.kinematics != Kinematics::Small)
    return Status::failure(
        "the element has small (SMALl) kinematics; it cannot change to FINIte here (HINGe2joint "
        "switches elements to finite kinematics)");
  const double l = length_;
  std::optional<InelasticFrame> fresh;
  try {
    const double full = fullLength();
    fresh.emplace(mat, nodes_, Vec2::Zero(), Vec2(full * rotation_(0, 0), full * rotation_(0, 1)),
                  rigid_.offsets());
  } catch (const std::invalid_argument& e) {
    return Status::failure(e.what());
  }
  const PointState& c = committed_;
  const double m = std::abs(c.forces.M);
  auto fmt = [](double v) {
    std::ostringstream s;
    s.precision(6);
    s << v;
    return s.str();
  };
  if (c.section.hingeActive) {
    if (!fresh->law_.softening())
      return Status::failure("its softening hinge is active: the SOFTening law cannot be removed");
    const LinearSoftening& law = *fresh->law_.softening();
    if (c.section.hingeFailed && law.capacity(c.section.jump.xi) > 0)
      return Status::failure(
          "its hinge is fully softened: the new SOFTening law would give it "
          "back a capacity of " +
          fmt(law.capacity(c.section.jump.xi)));
    if (m > law.capacity(c.section.jump.xi) * (1 + 1e-9))
      return Status::failure("its active hinge carries |M| = " + fmt(m) +
                             ", above the capacity Mu + Ks*xi = " + fmt(law.capacity(c.section.jump.xi)) +
                             " of the new SOFTening law");
  } else {
    if (fresh->law_.softening() && m > fresh->law_.softening()->Mu() * (1 + 1e-9))
      return Status::failure("its moment |M| = " + fmt(m) +
                             " is above the new Mu = " + fmt(fresh->law_.softening()->Mu()) +
                             " (the hinge would open past its capacity)");
    const double radius = fresh->law_.bending().yieldRadius(c.section.bulk.xi);
    if (m > radius * (1 + 1e-9))
      return Status::failure("its moment |M| = " + fmt(m) + " is above the yield moment " +
                             fmt(radius) + " of the new HARDening law at its hardening state");
  }
  // Target strains that give the committed section forces under the new data;
  // the stress-free displacement takes the rest of the current strains.
  const double ei = fresh->law_.EI();
  const Rows b = midpointRows(l);
  const ElemVec dl = toLocal_ * d;
  const double eps = c.forces.N / fresh->EA_, gamma = c.forces.V / fresh->GA_;
  const double kappaD = c.section.bulk.kp + (c.section.hingeActive ? c.section.jump.alpha / l : 0.0) + c.forces.M / ei;
  const double e0 = b.eps.dot(dl) - eps, g0 = b.gamma.dot(dl) - gamma,
               k0 = b.kappa.dot(dl) - kappaD;
  ElemVec dl0 = ElemVec::Zero();  // u2 = l e0, theta2 = l k0, v2 from gamma = v2/l - theta2/2
  dl0(3) = l * e0;
  dl0(5) = l * k0;
  dl0(4) = l * (g0 + 0.5 * dl0(5));
  EA_ = fresh->EA_;
  GA_ = fresh->GA_;
  rhoA_ = fresh->rhoA_;
  law_ = fresh->law_;
  axial_ = fresh->axial_;
  damping_ = fresh->damping_;
  mass_ = fresh->mass_;
  dl0_ = dl0;
  return Status::success();
}

}  // namespace c2d
