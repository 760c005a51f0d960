#pragma once
// The energy account of a run, kept step by step at every commit:
//   kinetic, strain (stored elastic energy of the elements), contact (penalty
//   energy), external (work of loads, self-weight and reactions since the start),
//   dissipated (everything the model turned into heat since the start: plastic
//   work of hardening and softening, the mid-point scheme's algorithmic
//   dissipation, contact dissipation; Newmark's energy error shows here too,
//   with either sign),
//   balance = kinetic + strain + contact - external + dissipated,
// which stays constant to the solver's tolerance in every analysis.
//
// The work of a step is taken at the step's load point with the forces the
// equations were solved with: under the mid-point scheme the algorithmic forces
// (every force of the residual is evaluated at the load point), otherwise the
// trapezoidal mean of the forces at t_n and t_n+1. With du = u_n+1 - u_n:
//   external   += du . loads + du . reactions (restrained dofs)
// (loads: FORCe, self-weight, floor loads, forces of removed members being released)
//   dissipated += du . f_elements - du . f_contact - change of (kinetic + strain + contact)
// where f_elements are the elements' internal and inertia forces. The balance
// then changes by du . R over the free dofs only, R the residual: zero at a
// converged state, so the balance measures how well the equations were solved
// and that every force is accounted for. Dissipation is not inferred from the
// balance: it is the work of the element forces that the elements did not store.
#include <istream>
#include <ostream>

#include "core/Assembler.h"
#include "core/State.h"
#include "core/StepRule.h"

namespace c2d {

struct Energy {
  double kinetic = 0, strain = 0, contact = 0;
  double external = 0;    // work of loads, self-weight and reactions since the start
  double dissipated = 0;  // since the start (see above), net of `restored`
  // What contacts gave back of the scheme's decay since the start
  // (core/contact/GroundContact.h groundImpactOwed): part of `dissipated`
  // taken back, not a gain without work.
  double restored = 0;
  double total() const { return kinetic + strain + contact - external; }
  double balance() const { return total() + dissipated; }
};

class EnergyAccount {
 public:
  // Books the step from the committed state to s (trial = converged), with the
  // assembler's last evaluation at s under `rule` and the load factors
  // `loadFactors` of that evaluation; loadFactorsN: the factors at t_n (used by
  // the trapezoidal rule).
  void commitStep(Assembler& a, const State& s, const StepRule& rule,
                  const Eigen::VectorXd& loadFactors, const Eigen::VectorXd& loadFactorsN);
  // The account now, with the energies of the last evaluation.
  Energy energy(Assembler& a, const State& s) const;
  // Node count changed (nodes appended): keeps the values of the existing nodes.
  void resize(int numNodes);
  // After a topology change at a committed state (a joint formed or ruptured):
  // the stored energy the next step starts from is the one of the new model.
  // What the change released at the committed positions is booked as
  // dissipated, as a fracture's: a joint formed in statics solves its relative
  // rotation for a zero end moment, and the moment the one-point element
  // carried there (its shear times half its length, the hinge's moment being
  // zero at the midpoint) is released with its energy. A change that stored
  // energy instead would be a fault: it stays in the balance, not taken back
  // as dissipation in the next step.
  void restartFrom(const Energy& now) {
    const double stored = now.kinetic + now.strain + now.contact;
    if (stored < storedN_) dissipated_ += storedN_ - stored;
    storedN_ = stored;
  }
  // Stored energy the commit released without work (a member contact whose
  // node was pushed past the centre line of the member: core/contact/PairMemories.h).
  void released(double energy) {
    storedN_ -= energy;
    dissipated_ += energy;
  }
  // Energy a contact gave back at the commit of what the scheme's decay had
  // taken from its impact: stored again, and the dissipation that took it
  // is taken back.
  void restored(double energy) {
    released(-energy);
    restored_ += energy;
  }
  // Elements left the model at the committed state (solvers/MemberRemoval.h),
  // per node dof: their forces of the last commit and the constant loads that
  // left with them (weight, floor loads); `after`: the energies of the model
  // without them. The stored energy that left is booked as dissipated. Under
  // the trapezoidal rule the forces at t_n are those the integrator starts the
  // next step from (Newmark's a_n was in equilibrium with the removed forces):
  // the difference the removal made is a load at t_n (the removed forces,
  // released over the next step, or over td through the released forces),
  // whose work is external.
  void removed(const Eigen::VectorXd& forces, const Eigen::VectorXd& weight, const Energy& after);

  void write(std::ostream& out) const;
  void read(std::istream& in);

 private:
  double external_ = 0, dissipated_ = 0, restored_ = 0;
  double storedN_ = 0;            // kinetic + strain + contact at t_n
  Eigen::VectorXd feN_, fcN_, rN_;  // element forces, contact forces, residual at t_n
  Eigen::VectorXd relN_;            // released forces of removed elements at t_n
};

}  // namespace c2d
