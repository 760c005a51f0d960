#pragma once
// [ext] INFIll,,t,fm[,Em[,rho[,open]]] with records "n1 n2 n3 n4 [ng dn]":
// masonry infill panels in the frame's bays, each as two compression-only
// diagonal struts (elements/InfillStrut.h, materials/InfillPanel.h). The
// struts are built once the members are (they take the columns' stiffness and
// the members' depths), numbered after the deck's elements in record order,
// two per panel: the strut n1-n3 first, then n2-n4.
#include <vector>

#include "macro/mesh/MeshCommands.h"

namespace c2d {

// Its entry of the mesh command table (macro/mesh/MeshCommands.cpp lists it).
std::vector<MeshCommandEntry> infillCommandTable();

}  // namespace c2d
