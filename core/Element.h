#pragma once
// The element contract. Narrow on purpose: nodes, residual + tangent for a trial
// state, mass, body load, commit/revert, report. Extra abilities are separate
// small interfaces (core/Hinge.h for softening hinges, core/io/Checkpoint.h for
// restart files); a joint is a decorator (elements/JointedElement.h).
//
// Trial state is a pure function of the committed state plus the trial kinematics:
// evaluate() may be called any number of times; only commit() changes history,
// and revert() drops the trial history.
#include <array>
#include <string>

#include "core/Error.h"
#include "core/StepRule.h"
#include "core/Types.h"

namespace c2d {

// Nodal values gathered for one element, global frame, element dof order.
struct ElementKinematics {
  ElemVec d;   // total displacement at t_{n+1} (trial)
  ElemVec dn;  // total displacement at t_n (committed)
  ElemVec vn;  // velocity at t_n
  ElemVec an;  // acceleration at t_n
};

// Section forces at a point of the element, in the element's (deformed) frame:
// N axial (tension +), V shear, M bending (counterclockwise on the positive face).
struct SectionForces {
  double N = 0, V = 0, M = 0;
};

class Element {
 public:
  virtual ~Element() = default;

  virtual std::array<int, 2> nodes() const = 0;  // 0-based node indices
  // False when the element puts no moment on the rotation of its node at `end`
  // (a revolute joint there): a node whose rotation no element holds has no
  // rotation equation (core/DofMap.h).
  virtual bool holdsRotation(int end) const { return end == 0 || end == 1; }
  virtual void setNodes(const std::array<int, 2>& n) = 0;
  virtual int materialNumber() const = 0;
  virtual std::string typeName() const = 0;  // "frame-timoshenko", "frame-reissner", ...

  // Residual r = f_int + M a_eff (no external loads) and its derivative dr/dd
  // (when wantTangent), for the trial kinematics under the step rule. Updates the
  // trial history. A failure (local equation not solved, non-finite values) is
  // returned, never thrown.
  virtual Status evaluate(const ElementKinematics& kin, const StepRule& rule, bool wantTangent,
                          ElemVec& residual, ElemMat& tangent) = 0;

  virtual ElemMat mass() const = 0;                    // constant mass matrix (global frame)
  virtual ElemVec bodyLoad(const Vec2& g) const = 0;   // consistent nodal loads of self-weight g

  virtual void commit() = 0;
  virtual void revert() = 0;

  // Stored (strain) energy at the last evaluated trial state; kinetic energy for
  // the given nodal velocities (elements with internal dofs add theirs).
  virtual double strainEnergy() const = 0;
  virtual double kineticEnergy(const ElemVec& v) const { return 0.5 * v.dot(mass() * v); }
  // Generalized momentum M v at the nodes (forces' conjugates: translations,
  // then the sections' angular momentum), for the same nodal velocities.
  virtual ElemVec momentum(const ElemVec& v) const { return mass() * v; }

  // Section forces at the element's reporting point (its integration point),
  // from the last evaluated state.
  virtual SectionForces sectionForces() const = 0;
};

}  // namespace c2d
