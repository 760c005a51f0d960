#pragma once
// Loads and masses the way engineers give a floor: a uniform load per unit
// length on an element in a global direction (QLOAd, e.g. a floor's dead plus
// live load on a beam, kN/m), optionally also carried as mass, and lumped
// nodal masses (MASS, t). Both enter the analysis through the assembler: the
// loads join the constant external load vector (like self-weight), the masses
// the inertia of the nodes they sit on, in statics (under GRAVity) and dynamics.
//
// A uniform load q on an element of reference length L goes half to each end
// node, qL/2, with no nodal moments: the consistent load of the two-node
// Timoshenko and Reissner elements (for the Hermite Euler-Bernoulli element the
// lumped one). A load carried as mass lumps m L/2, m = |q|/|g|, on each end
// node's translations; GRAVity does not load that mass again (q is its weight).
// Nodal masses act on their node's dofs (m1, m2 translations, m3 rotary
// inertia) and are loaded by GRAVity.
#include <array>
#include <vector>

#include "core/Model.h"
#include "core/Types.h"

namespace c2d {

// Constant nodal loads (per node dof, size numNodes*3) of the element loads and
// of the weight of the nodal masses under the model's gravity.
Eigen::VectorXd floorLoadVector(const Model& model);

// Lumped masses per node dof (size numNodes*3): the MASS records plus the
// element loads carried as mass.
Eigen::VectorXd lumpedNodalMass(const Model& model);

// The mass per unit length an element load carries: |q| / |g| when it is
// carried as mass (0 otherwise, or without gravity).
double carriedMassPerLength(const Model& model, const ElementLoad& load);

}  // namespace c2d
