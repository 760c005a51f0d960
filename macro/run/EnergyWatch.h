#pragma once
// What a run's energy account (solvers/EnergyAccount.h) says about the
// physics, kept at every commit:
//   - the balance's drift, max |balance - initial| / the largest energy scale
//     so far (the energy error of the summary): a force doing work the model
//     does not book, or a loose tolerance;
//   - the energy the motion gained without work: the sum over dynamic steps
//     of the dissipation's decrease. Every mechanism the model has (plastic
//     work, softening, dashpots, crushing, friction, the mid-point scheme's
//     algorithmic dissipation) takes energy out, so a step whose dissipation
//     is negative created energy. Newmark's trapezoidal rule does that for
//     nonlinear members (its energy error has either sign): an RC member
//     vibrating about N = 0, whose axial stiffness changes 5-20-fold there,
//     gains energy step after step until Newton fails. The run says so,
//     with when it began (the mid-point scheme, DYNAmic,ENERgy, conserves or
//     decays the energy by construction).
// Static steps are left out of the gain: their work is the trapezoidal mean
// of the forces, whose quadrature error has either sign and moves no mass.
#include <istream>
#include <ostream>
#include <string>

#include "solvers/EnergyAccount.h"

namespace c2d {

class EnergyWatch {
 public:
  void onCommit(const Energy& en, bool dynamic, int step, double t);

  // max |balance - initial| over the run, per the largest energy scale.
  double error() const { return error_; }
  // The energy gained without work, per the energy put in (the stored energy
  // at the start and the largest external work so far).
  double gained() const { return input_ > 0 ? gained_ / input_ : 0.0; }
  // The step and time at which the gain first exceeded kGainTolerance of the
  // energy put in (step 0: it never did).
  int gainStep() const { return gainStep_; }
  double gainTime() const { return gainTime_; }

  void save(std::ostream& out) const;
  void load(std::istream& in);

  // The gain the run warns about: 1 % of the energy put in. A gain below it is
  // the trapezoidal rule's discretization error with nonlinear members (the
  // paper's six-storey fall under Newmark, decks/paper/six_story_schemes.inp:
  // 0.1 %), shown by the summary; the mid-point scheme's runs gain round-off
  // (1e-16 to 1e-11 over the decks).
  static constexpr double kGainTolerance = 1e-2;

 private:
  bool started_ = false;
  double energy0_ = 0, scale_ = 0, error_ = 0;
  double stored0_ = 0, input_ = 0;  // the energy put in (see gained())
  double dissipatedN_ = 0;  // the committed dissipation
  double restoredN_ = 0;    // what contacts had restored of it (Energy::restored)
  double gained_ = 0;       // kJ
  int gainStep_ = 0;
  double gainTime_ = 0;
};

// What a gain (per the energy put in) that passed kGainTolerance at `step`,
// time t, means and what to do: the sentence of the run's warning and of a
// failure's advice.
std::string energyGainText(double gained, int step, double t);

}  // namespace c2d
