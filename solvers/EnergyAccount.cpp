#include "solvers/EnergyAccount.h"

#include "core/io/Checkpoint.h"

namespace c2d {

void EnergyAccount::resize(int numNodes) {
  const Eigen::Index nd = static_cast<Eigen::Index>(numNodes) * kNodeDofs;
  for (Eigen::VectorXd* v : {&feN_, &fcN_, &rN_, &relN_}) {
    const Eigen::Index old = v->size();
    v->conservativeResize(nd);
    if (nd > old) v->tail(nd - old).setZero();
  }
}

void EnergyAccount::commitStep(Assembler& a, const State& s, const StepRule& rule,
                               const Eigen::VectorXd& loadFactors,
                               const Eigen::VectorXd& loadFactorsN) {
  const Eigen::Index nd = s.u.size();
  if (feN_.size() != nd) resize(static_cast<int>(nd / kNodeDofs));
  const Eigen::VectorXd& r = a.nodalResidual();
  const Eigen::VectorXd& fc = a.contactForces();
  const Eigen::VectorXd& fRef = a.referenceLoad();
  const Eigen::VectorXd& fGrav = a.gravityLoad();
  const Eigen::VectorXd& fRel = a.releasedLoad();
  const DofMap& dofs = a.dofs();
  const bool midPoint = rule.scheme == Scheme::MidPoint;
  double external = 0, elements = 0, contact = 0;
  for (Eigen::Index i = 0; i < nd; ++i) {
    // The increment as the forces work on it: rotations by their rate measure
    // under the Cayley rule (core/StepRule.h).
    const double du = rule.rate(i, s.u[i] - s.un[i]);
    // The forces of this evaluation: r = f_elements - loads - f_contact.
    const double load = loadFactors[i] * fRef[i] + fGrav[i] + fRel[i];
    const double fe = r[i] + load + fc[i];
    const int n = static_cast<int>(i / kNodeDofs), d = static_cast<int>(i % kNodeDofs);
    const bool restrained = dofs.used(n) && dofs.restrained(n, d);
    if (midPoint) {
      external += du * load + (restrained ? du * r[i] : 0.0);
      elements += du * fe;
      contact += du * fc[i];
    } else {
      const double loadN = loadFactorsN[i] * fRef[i] + fGrav[i] + relN_[i];
      external += du * 0.5 * (load + loadN) + (restrained ? du * 0.5 * (r[i] + rN_[i]) : 0.0);
      elements += du * 0.5 * (fe + feN_[i]);
      contact += du * 0.5 * (fc[i] + fcN_[i]);
    }
    feN_[i] = fe;
    fcN_[i] = fc[i];
    rN_[i] = restrained ? r[i] : 0.0;
    relN_[i] = fRel[i];
  }
  const Energy now = energy(a, s);
  const double stored = now.kinetic + now.strain + now.contact;
  external_ += external;
  dissipated_ += elements - contact - (stored - storedN_);
  storedN_ = stored;
}

void EnergyAccount::removed(const Eigen::VectorXd& forces, const Eigen::VectorXd& weight,
                            const Energy& after) {
  if (feN_.size() != forces.size()) resize(static_cast<int>(forces.size() / kNodeDofs));
  // The residual at t_n, r = f_elements - loads - f_contact, stays what it was.
  feN_ -= forces;
  relN_ += weight - forces;
  const double stored = after.kinetic + after.strain + after.contact;
  dissipated_ += storedN_ - stored;
  storedN_ = stored;
}

Energy EnergyAccount::energy(Assembler& a, const State& s) const {
  Energy e;
  e.kinetic = a.kineticEnergy(s);
  e.strain = a.strainEnergy();
  e.contact = a.contactEnergy(s);
  e.external = external_;
  e.dissipated = dissipated_;
  e.restored = restored_;
  return e;
}

void EnergyAccount::write(std::ostream& out) const {
  using namespace checkpoint;
  putTag(out, "ENGY");
  for (double x : {external_, dissipated_, restored_, storedN_}) put(out, x);
  for (const Eigen::VectorXd* v : {&feN_, &fcN_, &rN_, &relN_}) putVector(out, *v);
}

void EnergyAccount::read(std::istream& in) {
  using namespace checkpoint;
  expectTag(in, "ENGY");
  for (double* x : {&external_, &dissipated_, &restored_, &storedN_}) *x = get<double>(in);
  for (Eigen::VectorXd* v : {&feN_, &fcN_, &rN_, &relN_}) *v = getVector(in);
  if (feN_.size() != fcN_.size() || feN_.size() != rN_.size() || feN_.size() != relN_.size())
    throw CheckpointError("energy account vectors differ in size");
}

}  // namespace c2d
