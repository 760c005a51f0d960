#pragma once
// A Newton correction from fresh factors, checked: K du = R must hold to
// |K du - R| <= kMaxMisfit |R|. A pivoting LU of a mechanism's tangent ends
// with round-off pivots and a correction that solves nothing; but a
// well-posed tangent that is only ill-conditioned (a near-rigid axial or
// shear stiffness, RESUltant STIFfness 1e9 1e10 EI, beside a softening
// hinge) can miss the check too when its factors did not pivot (the block
// LU pivots only within a node's block) and lost digits to cancellation.
// So before a tangent is called singular:
//   1. the correction is refined with the same factors (iterative
//      refinement, at most kRefinements sweeps), which recovers the digits a
//      stable enough factorization lost;
//   2. the tangent is factored again with partial pivoting
//      (LinearSolver::refactorWithPivoting: the auto solver moves to KLU
//      for the rest of the pattern, as when the block LU meets a
//      near-singular pivot block) and solved and refined again;
//   3. only a solve that still misses is a failure, and the diagnosis tells
//      an ill-conditioned tangent (its condition number estimate, 1-norm,
//      below kSingularCondition: the stiffnesses of the model span too many
//      decades for double precision) from a singular one (a mechanism).
#include <Eigen/Core>
#include <string>

#include "core/Error.h"
#include "solvers/linear/LinearSolver.h"

namespace c2d {

struct CheckedSolve {
  // Largest |K du - R| / |R| accepted (the regression decks stay below 2e-10).
  static constexpr double kMaxMisfit = 1e-6;
  static constexpr int kRefinements = 3;
  // A condition number estimate at or above this is a singular matrix in
  // double precision (1 / eps / 10).
  static constexpr double kSingularCondition = 4.5e14;

  double misfit = 0;      // |K du - R| / |R| of the correction returned
  int refinements = 0;    // sweeps of iterative refinement done
  bool pivoted = false;   // the tangent was factored again with pivoting
  double condition = -1;  // 1-norm condition estimate when the check failed (-1: none)
  bool singular = false;  // failed, and the tangent is singular (not just ill-conditioned)

  // du holds the solve of K du = R from the solver's fresh factors of K; on
  // success it holds a correction that passes the check. rho and drho are
  // work vectors (sized here only when they are not already).
  Status check(LinearSolver& solver, const SparseMatrix& K, const Eigen::VectorXd& R,
               Eigen::VectorXd& du, Eigen::VectorXd& rho, Eigen::VectorXd& drho);
  // After a failed check: "singular tangent: the solve leaves ... (a
  // mechanism?...)" or "ill-conditioned tangent (condition number estimate
  // ...): ...".
  std::string diagnosis() const;

 private:
  // Refines du with the solver's current factors until the check passes.
  bool refine(LinearSolver& solver, const SparseMatrix& K, const Eigen::VectorXd& R,
              Eigen::VectorXd& du, Eigen::VectorXd& rho, Eigen::VectorXd& drho);
};

}  // namespace c2d
