#pragma once
// The printed tables of the log, in FEAP's layout: a spaced title with the time
// and load factor, a column header, one row per node or element, a blank line.
#include <ostream>
#include <vector>

#include "core/Model.h"
#include "core/State.h"

namespace c2d {

enum class NodalQuantity { Displacement, Velocity, Acceleration, Reaction };

// nodes: 0-based node indices to print. values: every node dof (node*3 + dof).
// longFormat: FEAP's FORM,LONG (ten significant digits instead of five).
void printNodalTable(std::ostream& os, NodalQuantity q, const Model& model, const State& state,
                     double loadFactor, const Eigen::VectorXd& values,
                     const std::vector<int>& nodes, bool longFormat = false);

void printStressTable(std::ostream& os, Model& model, const State& state, double loadFactor,
                      const std::vector<int>& elements);

// activationStep: per element, the step its hinge formed (0 if none). Lists the
// midpoint hinges, then the joints of the hinges opened at element ends.
void printHingeTable(std::ostream& os, Model& model, const State& state, double loadFactor,
                     const std::vector<int>& activationStep);

}  // namespace c2d
