#pragma once
// When a Newton iteration has converged, and when it has stopped making
// progress. Figures per iteration: the energy |du.R| of the correction (with
// the load-factor part under path following) and the residual norm ||R||
// before the update.
//
// Converged when any of these holds:
//   - FEAP's energy test: |du.R| <= energyTol * |du.R| of the step's first
//     iteration (TOL,,etol), or below FEAPpv's absolute value (TOL,ENER,value);
//   - the residual test: ||R|| <= residualTol * ||R|| of the step's first
//     iteration (TOL,,etol,rtol; off when 0);
//   - the residual already at round-off of the largest element force (not
//     under path following, whose load factor still moves);
//   - stagnation at round-off: the energy no longer falls tenfold although it
//     is already 1e-10 of the first one;
//   - a correction below the resolution of the nodal positions (a free body
//     in uniform motion is predicted exactly; its residual is round-off of zero).
#include <cstddef>

namespace c2d {

struct ConvergenceTest {
  double energyTol = 1e-16;
  double residualTol = 0;
  double energyZero = 0;

  struct Figures {
    int iteration = 1;             // within the step, 1-based
    double energy = 0;             // |du.R| of this iteration
    double energy0 = 0;            // of the step's first iteration
    double previousEnergy = -1;    // of the iteration before (< 0: none)
    double residual = 0;           // ||R|| before this update
    double residual0 = 0;          // of the step's first iteration
    double largestResidual = 0;    // max |R_i|
    double roundoff = 0;           // round-off level of the element forces
    double largestCorrection = 0;  // max |du_i|
    double positions = 0;          // largest coordinate plus displacement magnitude
    bool pathFollowing = false;
  };
  bool converged(const Figures& f) const;
};

// Newton's method cycling: each of the last `matches` values equals the one
// `period` iterations before (to 1e-6 relative). On a kinked constitutive law
// the iterates jump between the branches (period two) or come back to the
// same residual (period one), and no later iteration converges.
// values[0 .. n-1] in iteration order.
bool repeatsWithPeriod(const double* values, std::size_t n, int period, int matches,
                       double tolerance = 1e-6);

// Newton's iterates have stopped making progress: for a period p from 1 to
// maxPeriod, the last values repeat with period p to `tolerance` relative,
// over a whole period (two values for p = 1). Contact laws with several
// kinks (entering, crushing, unloading, sticking, sliding) send the iterates
// round cycles of period three to six as well, and approach a cycle only
// geometrically: at 1e-6 a cycle of period two took 15 iterations to be seen.
bool stopsProgressing(const double* values, std::size_t n, int maxPeriod, double tolerance);

// Newton's iterates run away from the solution: the residuals of the last
// three iterations increase, and the last is above kDivergence times the
// least of the step after its first iteration (the first is the committed
// state's, about zero in a displacement-controlled step). A static step whose
// sections passed a kink of their law in the first correction (a member's
// first yield, beyond which an RC section's law is almost flat up to Mu: its
// tangent 1000 times below EI) takes a curvature jump of the residual over
// that tangent in the next; with finite rotations the jump turns elements by
// tenths of a radian, stretches them past their bars' yield, and every later
// iterate is further off. values[0 .. n-1] in iteration order.
constexpr double kDivergence = 100;
bool runsAway(const double* residuals, std::size_t n);

}  // namespace c2d
