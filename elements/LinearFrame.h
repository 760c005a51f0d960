#pragma once
// Geometrically linear 2-node frame element (deck: FRAMe + SMALl, elastic).
//
// SHEAr ON: Timoshenko beam, linear interpolation of u, v, theta and one-point
// (midpoint) integration of every term, which keeps the element free of shear
// locking. SHEAr OFF: Euler-Bernoulli beam, linear axial and cubic Hermite
// bending interpolation, exact stiffness.
//
// Element frame: t = (x2 - x1)/l along the axis, n = (-t_y, t_x); local dofs
// (u_t, u_n, theta) per node. Strains: eps = u_t', gamma = u_n' - theta,
// kappa = theta'. Resultants N = EA eps, V = GA gamma, M = EI kappa.
//
// A material change (core/MaterialChange.h) keeps the end forces at the
// committed displacements d_c: the element then works on d - d0 with the
// stress-free displacement d0 chosen so that K_new (d_c - d0) equals the old
// end forces (d0 has no rigid-body part; zero unless the material changed).
//
// Rigid end zones (elements/RigidEnds.h): the stiffness is that of the flexible
// length between the faces, mapped to the nodes (K = G^T K_flex G); mass and
// self-weight stay those of the full length between the nodes.
#include <array>
#include <string>

#include "core/io/Checkpoint.h"
#include "core/Element.h"
#include "core/MaterialChange.h"
#include "core/MaterialSet.h"
#include "elements/RigidEnds.h"
#include "materials/SectionDamping.h"

namespace c2d {

class LinearFrame final : public Element, public Checkpoint, public MaterialChange {
 public:
  // offsets: the rigid end zones at the first and second node (m).
  LinearFrame(const MaterialSet& mat, const std::array<int, 2>& nodes, const Vec2& x1,
              const Vec2& x2, const std::array<double, 2>& offsets = {0.0, 0.0});

  std::array<int, 2> nodes() const override { return nodes_; }
  void setNodes(const std::array<int, 2>& n) override { nodes_ = n; }
  int materialNumber() const override { return materialNumber_; }
  std::string typeName() const override;

  // Static/Newmark: r = K d + M a_eff. MidPoint: r = K((1/2+alpha) d + (1/2-alpha) dn) + M a_eff.
  // A damped section (DAMPing) adds a1 K (d - dn)/h in dynamics (materials/SectionDamping.h).
  Status evaluate(const ElementKinematics& kin, const StepRule& rule, bool wantTangent,
                  ElemVec& residual, ElemMat& tangent) override;

  ElemMat mass() const override { return mass_; }
  ElemVec bodyLoad(const Vec2& g) const override;

  void commit() override { committed_ = trial_; }
  void revert() override { trial_ = committed_; }

  // 1/2 d.K d at the last evaluated d_{n+1}.
  double strainEnergy() const override { return trial_.energy; }
  // N, V, M at the element midpoint for the last evaluated d_{n+1} (every scheme).
  SectionForces sectionForces() const override { return trial_.forces; }

  double length() const { return length_; }  // the flexible length
  const RigidEnds& rigidEnds() const { return rigid_; }
  double fullLength() const { return length_ + rigid_.offset(0) + rigid_.offset(1); }
  bool shear() const { return shear_; }
  const ElemMat& stiffness() const { return stiffness_; }  // global frame
  // Element-frame resultants (N, V, M) at the midpoint for nodal displacements d (global).
  SectionForces forcesAt(const ElemVec& d) const;

  // Restart files: every member after the construction data.
  void writeState(std::ostream& out) const override;
  void readState(std::istream& in) override;

  // New E, nu, A, I, kappa (or resultants), SHEAr, density and mass type; end
  // forces kept. Refuses FINIte kinematics and HARDening/SOFTening data (an
  // elastic frame cannot become an inelastic one).
  Status setMaterial(const MaterialSet& mat, const ElemVec& d) override;
  const ElemVec& stressFreeDisplacement() const { return d0_; }

 private:
  struct Report {
    double energy = 0;
    SectionForces forces;
  };

  std::array<int, 2> nodes_;
  int materialNumber_ = 0;
  bool shear_ = true;
  double length_ = 0;  // between the faces
  RigidEnds rigid_;
  double cos_ = 1, sin_ = 0;  // axis direction
  double ea_ = 0, ga_ = 0, ei_ = 0, rhoA_ = 0;
  SectionDamping damping_;
  ElemMat stiffness_;  // global frame
  ElemMat mass_;       // global frame
  Report trial_, committed_;
  ElemVec d0_ = ElemVec::Zero();  // stress-free displacement (global frame)
};

}  // namespace c2d
