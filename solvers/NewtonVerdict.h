#pragma once
// What a Newton loop does after an iteration that neither failed nor began a
// part of its step (a restart from the committed state, a landing time, an
// impact's shorter step): the convergence test's answer (ConvergenceTest,
// Analysis::iterate) together with the step's tests of no progress.
#include <vector>

namespace c2d {

struct IterationInfo;

enum class NewtonVerdict {
  Converged,  // the convergence test passed: the loop ends
  Iterating,  // the loop goes on
  Stalled,    // no later iteration converges: the step is cut or reported now
  Diverged,   // the energy blew up: the step is cut or reported now
};

// Above this ratio of the step's first energy |du.R| the iterates have diverged.
constexpr double kNewtonBlowUp = 1e30;

// The checks, in this order:
//   - diverged: more than four iterations, and the energy above kNewtonBlowUp
//     times the step's first (whatever the convergence test said);
//   - stalled: not converged after six iterations or more, and each of the last
//     three energies equal to the one two iterations before (to 1e-6): a fixed
//     point or a two-cycle of Newton's method that the line search did not break;
//     once the line search took over in the step (the iteration marked
//     `globalized`), only the iterations after it count (a freshly opened hinge
//     at the end of a short link, whose slip stiffness is its rotary inertia
//     alone, cycles plain Newton across its stick band at every step length;
//     the line search's iterations converge it);
//   - converged: the convergence test passed (info.converged);
//   - iterating otherwise.
// `history`: the step's iterations so far (Analysis::stepHistory), ending with `info`'s.
NewtonVerdict newtonVerdict(const IterationInfo& info, const std::vector<IterationInfo>& history);

}  // namespace c2d
