#pragma once
// The summary of a run (ProblemRun::summary) and of a deck's runs together
// (operator+=), its one-line text and the warnings it gives.
#include <string>
#include <vector>

namespace c2d {

struct RunSummary {
  int steps = 0, iterations = 0, factorizations = 0, cuts = 0, hinges = 0;
  // max |balance - initial balance| / max energy scale, the balance being kinetic + strain +
  // contact - external + dissipated (solvers/EnergyAccount.h): how well the run's energy
  // account closes, in static and dynamic runs
  double energyError = 0;
  // The energy the motion gained without work per the energy put in
  // (macro/run/EnergyWatch.h), and the step and time it passed the warning's
  // tolerance (0: it did not).
  double energyGained = 0;
  int gainStep = 0;
  double gainTime = 0;
  double seconds = 0;
  bool dynamic = false;         // some step was dynamic
  double maxMomentRatio = 0;    // largest |M|/Mu of an element with a softening law, any time
  int jointsFormed = 0, jointsRuptured = 0;  // during the run (fully softened hinges, ruptures)
  int fractures = 0;                          // members parted at their bars' fracture
  int shears = 0;                             // members parted by a shear failure
  int removed = 0;                            // elements removed (BLASt, REMOve)
  int crossings = 0;  // pairs of members crossing each other at the end
  int folded = 0;     // RC members bent through more than a quarter turn at the end
  int sunk = 0;       // runs in which a node went deeper into the ground than half its section
  bool memberContact = false;  // the crossing members had member contact (CONTact MEMBers)
  // BLASt records whose time the run never reached, or whose elements had all
  // been removed before (REMOve): they removed nothing.
  int blastsNotMade = 0;
  // Runs that ended with ground contact (debris figures), and those of them whose
  // debris left the site (SITE).
  int debrisRuns = 0, outsideRuns = 0;
  // Runs whose debris was still moving at the end (its kinetic energy above
  // TIME,REST's ratio of its peak), and the largest such ratio.
  int movingRuns = 0;
  double kineticRatio = 0;
  // Runs whose building did not go as SITE's dir intends (macro/output/FallVerdict.h),
  // and the verdict of the last of them.
  int unintendedRuns = 0;
  std::string verdict = {};

  // Adds the summary of another run: counts and times summed, the largest
  // errors and ratios kept (the largest energy gain with its step and time),
  // the flags or-ed, the last run's verdict of an unintended fall kept.
  RunSummary& operator+=(const RunSummary& s);
};

// The summary of a run: steps, iterations, cuts, hinges, joints formed and
// ruptured, debris outside the site, the largest |M|/Mu, the energy error (the
// largest change of the energy balance kinetic + strain + contact - external +
// dissipated over the largest energy of the run, solvers/EnergyAccount.h),
// wall time.
std::string runSummaryText(const RunSummary& s);
// Above this energy error a run is warned about: the balance closes to the
// Newton tolerance in every analysis, static or dynamic.
constexpr double kEnergyBalanceTolerance = 1e-6;
// The warnings a run's summary gives, one line each: an energy balance that
// changed by more than kEnergyBalanceTolerance, members crossing at the end,
// blasts whose time the run never reached.
std::vector<std::string> runWarnings(const RunSummary& s);

}  // namespace c2d
