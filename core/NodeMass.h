#pragma once
// The mass that moves with each node's translation (t): its share of the
// elements' masses, the row sums of the translational blocks of their mass
// matrices (a consistent matrix's lumped mass: a uniform member gives each end
// half its mass), plus the node's lumped masses (MASS, QLOAd carried as mass).
// A shared joint's slave moves with its master: its mass counts at the master
// and it has none of its own. A node whose translations are both restrained
// does not move: its mass is infinite. The contacts take it as the mass of a node (the
// critical damping 2 sqrt(k m) of a contact's dashpot, the peak of an impact
// whose turn falls inside a step: core/contact/ContactDamper.h, core/contact/CrushingLaw.h).
#include <vector>

#include "core/Model.h"

namespace c2d {

std::vector<double> translationalMasses(const Model& model);

}  // namespace c2d
