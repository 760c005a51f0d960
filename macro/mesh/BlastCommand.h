#pragma once
// [ext] The mesh command of a demolition's blast plan:
//   BLASt  records "t n1 n2 inc td": elements n1..n2 (step inc) are removed at
//          time t, their forces on the rest released linearly over td (0 or
//          empty: at once); solvers/MemberRemoval.h says what a removal does.
// Times and element numbers are expressions, so a SWEEp or LOOP over
// parameters is a study of blast plans.
#include <vector>

#include "macro/mesh/MeshCommands.h"

namespace c2d {

// Its entry of the mesh command table (macro/mesh/MeshCommands.cpp lists it).
std::vector<MeshCommandEntry> blastCommandTable();

}  // namespace c2d
