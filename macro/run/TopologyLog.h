#pragma once
// The log line of each topology event of a run (solvers/TopologyEvents.h):
// joints formed at failed hinges and ruptured, hinges opened at element ends
// (their joints made), members separated at the fracture of their bars or at
// their shear failure.
#include <ostream>

#include "core/Model.h"
#include "macro/run/LogFolding.h"
#include "solvers/TopologyEvents.h"

namespace c2d {

struct TopologyCounts {
  int hinges = 0;          // hinges opened at element ends
  int jointsFormed = 0;    // at fully softened hinges
  int jointsRuptured = 0;  // past thetaR
  int fractures = 0;       // members separated at their bars' fracture
  int shears = 0;          // members separated by a shear failure
  LogFolding folding;      // the lines that repeat (a joint held in every step)
};

void logTopologyEvent(std::ostream& log, const Model& model, double t, const TopologyEvent& ev,
                      TopologyCounts& counts);

}  // namespace c2d
