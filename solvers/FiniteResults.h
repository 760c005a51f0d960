#pragma once
// A result that is not a finite number (inf, NaN) is never written as if it
// were one: at every commit the state (displacements, velocities,
// accelerations, time), the nodal forces (reactions: the residual of the
// commit's assembly), every element's section forces and the energy account
// are checked, and the first value that is not finite is named, so that the
// run ends as a failed analysis there (with the command, step and time)
// instead of writing inf and NaN into its time history under a clean summary
// (an energy error of inf - inf is NaN, which no comparison catches).
#include <string>

#include "core/Model.h"
#include "core/State.h"
#include "solvers/EnergyAccount.h"

namespace c2d {

// The first non-finite value, e.g. "the displacement of node 3, dof 2 is inf"
// or "the contact energy is nan"; empty when every value is finite.
// nodalResidual: every node dof (node * 3 + dof).
std::string nonFiniteResult(const Model& model, const State& state,
                            const Eigen::VectorXd& nodalResidual, const Energy& energy);

}  // namespace c2d
