#pragma once
// Ability of an element to carry a softening plastic hinge (embedded rotation
// discontinuity). Activation is decided globally, one hinge at a time, so that
// a uniform moment localizes in exactly one element: after a converged Newton
// iteration the solver asks every inactive hinge for its demand |M|/Mu and
// activates the largest one above 1, then iterates again.
//
// The same machinery locates the fracture of an RC member's bars (axial strain
// eu, materials/AxialCapacity) and its shear failure (|V| reaching Vu(N),
// materials/ShearResistance): the demand is the largest of the hinge's, the
// bars' (strain / eu) and the shear's (|V| / Vu), and activation does whichever
// is the largest.
#include <istream>

#include "core/io/Checkpoint.h"
#include "core/Types.h"

namespace c2d {

// How far past its capacity (|M|/Mu - 1) a committed state may carry a member
// before the run warns, naming the element and the time. Hinge events are
// located to 1e-12 (solvers/HingeEvents.h); where the step's solution jumps
// across Mu between two sub-steps (another branch of a contact or a law), the
// hinge opens at the first state found past it (up to 3e-4 past Mu in the main
// example before its localization zones, 1.9e-3 in one run at half its step),
// a small fraction of the scatter of a section's strength.
// Beyond 0.1 % the result is not the model's.
constexpr double kCapacityTolerance = 1e-3;

struct HingeInfo {
  bool active = false;        // jump activated
  bool failed = false;        // fully softened: moment down to zero, a free hinge
  double position = 0.5;      // critical point s_d / l_e along the element
  double jump = 0;            // rotation jump alpha (rad)
  double moment = 0;          // hinge moment t (signed)
  double softening = 0;       // softening variable xi = |alpha| accumulated
  double ultimate = 0;        // the ultimate moment Mu of the law
  int count = 0;              // hinges opened in the element (hinges at its ends: up to 2)
  bool jointDue = false;      // a hinge opened at an end, its joint not made yet
  bool fracture = false;      // the bars fractured or the member failed in shear, not yet separated
  bool shear = false;         // that fracture is a shear failure (|V| at Vu(N))
};

class HingeCarrier {
 public:
  virtual ~HingeCarrier() = default;
  // |M|/Mu at the critical point of the last evaluated trial state (or the
  // bars' strain / fracture strain, whichever is larger); 0 when the element
  // has no softening law and no bars, or nothing left to open.
  virtual double hingeDemand() const = 0;
  // Activate the hinge (or the fracture) of the larger demand in the trial state
  // (made permanent by commit(), dropped by revert()).
  virtual void activateHinge() = 0;
  virtual HingeInfo hinge() const = 0;  // at the last evaluated trial state
  // The width of the band above 1 in which a located event opens the hinge:
  // the demand's round-off (solvers/HingeEvents).
  virtual double demandBand() const { return 1e-12; }
  // A hinge that may open below its capacity: one at a member's end, whose
  // joint is rigid until its moment reaches the capacity C(xi, N), so that
  // opening it early changes nothing before then. At the trial state: the
  // end (0: node 1, 1: node 2) of the largest demand when that demand is
  // such a hinge's (not a fracture's), else -1.
  virtual int earlyEnd() const { return -1; }
  // Opens the hinge at that end in the trial state, whatever its demand.
  virtual void activateHingeAt(int /*end*/) {}
};

// A member whose laws follow its axial force and whose bars can fracture or
// that can fail in shear (RC sections, hand-given laws with an interaction
// curve): the hinge laws of the joints at its ends (elements/JointedElement)
// follow its axial force, and after the commit that made a fracture or a shear
// failure permanent a topology event separates the member from one of its
// ends (elements/BarFractures.h) and reports it done.
//
// The member's parting, one state: whole, bars fractured or sheared (the
// separation due), separated.
// Restart files keep the number.
enum class Parting { Whole = 0, BarsFractured = 1, Separated = 2, Sheared = 3 };
inline Parting getParting(std::istream& in) {
  const int n = checkpoint::get<int>(in);
  if (n < 0 || n > 3) throw CheckpointError("an element's parting state is not one");
  return static_cast<Parting>(n);
}
class RcMember {
 public:
  virtual ~RcMember() = default;
  // Axial force of the last evaluated state (tension positive) and its
  // derivative with respect to the element's displacements d.
  virtual double axialForce() const = 0;
  virtual ElemVec axialForceGradient() const = 0;
  // Whether its laws follow the axial force at all (else the above are not needed).
  virtual bool followsAxialForce() const = 0;
  // A committed fracture or shear failure not yet separated.
  virtual bool fractureDue() const = 0;
  // The committed parting (its cause while due).
  virtual Parting parting() const = 0;
  // Shear |V| and the shear capacity Vu(N) at the last evaluated state (Vu 0:
  // the member does not fail in shear).
  virtual double shearForce() const = 0;
  virtual double shearCapacity() const = 0;
  virtual void fractureDone() = 0;
};

}  // namespace c2d
