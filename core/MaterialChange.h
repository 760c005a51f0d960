#pragma once
// Ability of an element to take new data of its material set in the middle of
// an analysis (MATErial given again in a MESH re-entry). Not part of the element
// contract (core/Element.h): elements/MaterialUpdate applies a material set to
// every element of that set that has this ability.
//
// The change is incremental: the element keeps its section forces at the
// committed state, and the new stiffness acts on the deformation from there on
// (an initial strain absorbs the difference, as HINGE2JOINT does). The history
// (plastic curvature, hardening variable, hinge state and jump, initial strain)
// is kept and continues under the new laws. A change the element cannot take
// (another kinematics, another element class, a law that would leave its
// history outside the new yield or softening surface) is returned as a failure
// that says why, and leaves the element unchanged.
//
// With the forces kept and the stiffness changed, the stored energy changes at
// the switch (W = 1/2 f.C^-1.f): the energy balance of a run has a step there,
// the work of the change.
#include "core/Error.h"
#include "core/MaterialSet.h"
#include "core/Types.h"

namespace c2d {

class MaterialChange {
 public:
  virtual ~MaterialChange() = default;
  // d: the element's committed total displacements (global frame, element dof
  // order, as the element sees them), the state its committed history belongs
  // to. The new data hold from the next evaluation on.
  virtual Status setMaterial(const MaterialSet& mat, const ElemVec& d) = 0;
};

}  // namespace c2d
