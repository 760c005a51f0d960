#pragma once
// [ext] WEAKen, records "factor n1 [n2 [inc]]": elements n1..n2 (step inc),
// members or infill struts, keep the share `factor` (0 < factor <= 1) of
// their strength and stiffness from the start (walls cut, cores opened, bars
// cut before the blast). A member takes a weakened copy of its material set
// (materials/WeakenedSet.h: exactly a member of a weaker set); an infill strut
// scales its law (materials/StrutLaw.h). Applied once the elements are built;
// an element weakened twice, absent, or that existed before a MESH re-entry
// is a deck error at its record.
#include <vector>

#include "macro/mesh/MeshCommands.h"

namespace c2d {

// Its entry of the mesh command table (macro/mesh/MeshCommands.cpp lists it).
std::vector<MeshCommandEntry> weakenCommandTable();

}  // namespace c2d
