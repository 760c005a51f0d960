#pragma once
// The finite element model: nodes, boundary conditions, proportional loads and
// prescribed values, material sets, elements, joints, ground contact, gravity.
// Node and element numbers are 0-based here; the deck's are 1-based.
#include <array>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "core/Element.h"
#include "core/Error.h"
#include "core/MaterialSet.h"
#include "core/Site.h"
#include "core/Types.h"

namespace c2d {

// Revolute joint between two coincident nodes: same translations, free relative rotation.
enum class JointForm {
  Condensed,  // the paper's: slave rotation = master + relative rotation, condensed in the element
  Shared,     // the slave keeps its own rotation dof and shares the master's translation dofs
};

struct Joint {
  int master = -1, slave = -1;
  JointForm form = JointForm::Condensed;
};

// Rigid ground y = y0 with penalty stiffness k per node (kN/m); zeta the
// damping ratio of the contact's dashpot (fraction of the critical damping
// 2 sqrt(k m) of each node's own mass m: core/contact/ContactDamper.h; 0: none); mu
// the coefficient of the elastic-plastic Coulomb friction (0: frictionless);
// restitution the coefficient e of an impact (1: elastic; below 1 the contact
// crushes: core/contact/GroundContact.h).
struct Ground {
  double y0 = 0, k = 0, zeta = 0, mu = 0, restitution = 1;
};

// Penalty contact between members (core/contact/MemberContact.h): stiffness k,
// damping ratio zeta (of the pair's reduced mass), restitution and friction
// coefficient mu as for the ground, and the contact radius of members whose
// material gives no section (negative: 1e-3 of the shortest element).
struct MemberContactData {
  double k = 0, zeta = 0, radius = -1, restitution = 1, mu = 0;
};

// Uniform load per unit reference length on an element, global components
// (QLOAd); asMass: the load is a weight, |q|/|g| is also mass (core/FloorLoad.h).
struct ElementLoad {
  int element = -1;
  Vec2 q = Vec2::Zero();
  bool asMass = false;
};

// Elements removed at a given time (BLASt; REMOve removes at once): their
// stiffness, mass, self-weight, loads and contact leave the model, and the
// forces they exerted on the rest are released linearly over `release`
// (0: at once). Element indices 0-based.
struct Blast {
  double time = 0;
  std::vector<int> elements;
  double release = 0;
  bool done = false;
  // Where the deck gave it (the BLASt record), for the messages about it; not
  // in restart files (a restarted run names a blast by its time).
  SourceLoc origin;
};

// The nodal forces a removed element exerted on the rest of the model
// (global frame, element dof order), applied as a load that falls linearly
// from its full value at `start` to zero at start + duration.
struct ReleasedForce {
  std::array<int, 2> nodes{-1, -1};
  ElemVec force = ElemVec::Zero();
  double start = 0, duration = 0;
  // The factor of the force at time t: 1 at the start, 0 from its end on.
  double factor(double t) const {
    if (t <= start) return 1.0;
    return t >= start + duration ? 0.0 : 1.0 - (t - start) / duration;
  }
};

class Model {
 public:
  // --- nodes ---
  int numNodes() const { return static_cast<int>(coords_.size()); }
  void resizeNodes(int n);
  const Vec2& coord(int node) const { return coords_[node]; }
  void setCoord(int node, const Vec2& x) {
    coords_[node] = x;
    defined_[node] = 1;
  }
  bool hasCoord(int node) const { return defined_[node]; }
  int addNode(const Vec2& x);  // appends a node with the same data layout; returns its index

  // Restraint codes (nonzero = restrained), proportional nodal forces and prescribed values.
  std::array<int, kNodeDofs>& bound(int node) { return bound_[node]; }
  const std::array<int, kNodeDofs>& bound(int node) const { return bound_[node]; }
  std::array<double, kNodeDofs>& force(int node) { return force_[node]; }
  const std::array<double, kNodeDofs>& force(int node) const { return force_[node]; }
  std::array<double, kNodeDofs>& disp(int node) { return disp_[node]; }
  const std::array<double, kNodeDofs>& disp(int node) const { return disp_[node]; }
  // Proportional load table of each dof's FORCe/DISPlacement value (FPROportional;
  // 0: table 1).
  std::array<int, kNodeDofs>& loadTable(int node) { return table_[node]; }
  const std::array<int, kNodeDofs>& loadTable(int node) const { return table_[node]; }
  // Lumped nodal mass of each dof (MASS: m1, m2 translations, m3 rotary inertia).
  std::array<double, kNodeDofs>& nodalMass(int node) { return mass_[node]; }
  const std::array<double, kNodeDofs>& nodalMass(int node) const { return mass_[node]; }

  // --- materials and elements ---
  std::map<int, MaterialSet>& materials() { return materials_; }
  const std::map<int, MaterialSet>& materials() const { return materials_; }
  const MaterialSet* material(int number) const;

  int numElements() const { return static_cast<int>(elements_.size()); }
  Element& element(int e) { return *elements_[e]; }
  const Element& element(int e) const { return *elements_[e]; }
  // False for an element number the mesh did not define or one removed (BLASt,
  // REMOve): its slot stays empty so that element numbers never change.
  bool hasElement(int e) const { return elements_[e] != nullptr; }
  void setElement(int e, std::unique_ptr<Element> el);  // grows the list as needed
  // Takes element e out of the model (its slot stays empty); bumps the topology.
  std::unique_ptr<Element> removeElement(int e);
  // Per node: 1 when an element holds it (a node no element holds is not part
  // of the structure: not drawn, not debris).
  std::vector<char> heldNodes() const;
  std::vector<std::unique_ptr<Element>>& elements() { return elements_; }
  const std::vector<std::unique_ptr<Element>>& elements() const { return elements_; }

  // --- collapse-phase features ---
  std::vector<Joint>& joints() { return joints_; }
  const std::vector<Joint>& joints() const { return joints_; }
  std::optional<Ground>& ground() { return ground_; }
  const std::optional<Ground>& ground() const { return ground_; }
  std::optional<MemberContactData>& memberContact() { return memberContact_; }
  const std::optional<MemberContactData>& memberContact() const { return memberContact_; }
  Vec2& gravity() { return gravity_; }
  const Vec2& gravity() const { return gravity_; }
  std::vector<ElementLoad>& elementLoads() { return elementLoads_; }
  const std::vector<ElementLoad>& elementLoads() const { return elementLoads_; }
  std::optional<Site>& site() { return site_; }
  const std::optional<Site>& site() const { return site_; }
  std::vector<Blast>& blasts() { return blasts_; }
  const std::vector<Blast>& blasts() const { return blasts_; }
  std::vector<ReleasedForce>& releasedForces() { return released_; }
  const std::vector<ReleasedForce>& releasedForces() const { return released_; }

  // Bumped whenever the dof structure may change (MESH re-entry, HINGE2JOINT):
  // the dof map, sparsity pattern and symbolic factorization are rebuilt.
  int topologyVersion() const { return topologyVersion_; }
  void bumpTopology() { ++topologyVersion_; }

  // Mesh size used for coordinate matching tolerances (EBOU, CBOU).
  double characteristicLength() const;

 private:
  std::vector<Vec2> coords_;
  std::vector<char> defined_;
  std::vector<std::array<int, kNodeDofs>> bound_, table_;
  std::vector<std::array<double, kNodeDofs>> force_, disp_, mass_;
  std::map<int, MaterialSet> materials_;
  std::vector<std::unique_ptr<Element>> elements_;
  std::vector<Joint> joints_;
  std::optional<Ground> ground_;
  std::optional<MemberContactData> memberContact_;
  Vec2 gravity_ = Vec2::Zero();
  std::vector<ElementLoad> elementLoads_;
  std::optional<Site> site_;
  std::vector<Blast> blasts_;
  std::vector<ReleasedForce> released_;
  int topologyVersion_ = 0;
};

// Node n's position under the displacements u (per node dof, as State holds them).
inline Vec2 nodePosition(const Model& model, const Eigen::VectorXd& u, int n) {
  return Vec2(model.coord(n).x() + u[kNodeDofs * n], model.coord(n).y() + u[kNodeDofs * n + 1]);
}

}  // namespace c2d
