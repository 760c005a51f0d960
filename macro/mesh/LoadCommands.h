#pragma once
// [ext] Mesh commands for floor loads, masses, gravity and the demolition site:
//   QLOAd  records "n1 n2 inc qx qy [MASS]": uniform load per unit length on
//          elements n1..n2 (step inc), global components; MASS: it is a weight,
//          |q|/|g| is also mass (core/FloorLoad.h)
//   MASS   records "node ng m1 m2 m3": lumped nodal masses (FEAP's nodal mass
//          input), generation by linear interpolation as for FORCe
//   SITE,,xmin,xmax   the zone the debris must stay in (macro/output/Debris.h)
//   GRAVity,,gx,gy    the self-weight of every element with a density
#include <vector>

#include "macro/mesh/MeshCommands.h"

namespace c2d {

// Their entries of the mesh command table (macro/mesh/MeshCommands.cpp lists them).
std::vector<MeshCommandEntry> loadCommandTable();

}  // namespace c2d
