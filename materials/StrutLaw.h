#pragma once
// The axial law of an infill panel's equivalent diagonal strut (INFIll): a
// compression-only masonry strut, elastic to its strength, softening linearly
// to a residual, then gone (elements/InfillStrut.h; docs/design/infill.md).
//
// In the shortening strain s = -eps (eps the strut's axial strain, tension +)
// the envelope of the compressive force P is piecewise linear through
//   (0, 0), (s_p, Pu), (5 s_p, r Pu), (8 s_p, r Pu), (10 s_p, 0),   s_p = Pu / K,
// with K = Em a t the strut's axial stiffness (force per unit strain), Pu its
// strength and r = 0.2 the residual. Unloading and reloading follow the secant
// to the origin through the largest shortening reached (a damage law: one
// history variable); in tension the strut carries nothing. From 10 s_p on the
// strut is gone: it carries nothing whatever its strain. Units: forces as the
// deck's (kN); strains dimensionless.
namespace c2d {

struct StrutLawState {
  double kappa = 0;     // largest shortening strain reached
  bool gone = false;    // crushed past the end of the residual, or its panel crushed
  // The panel's other strut crushed: this one goes as soon as it carries
  // nothing (a force that never jumps).
  bool doomed = false;
};

struct StrutResponse {
  double N = 0;        // axial force, tension + (so N <= 0)
  double dN = 0;       // dN / d eps
  double energy = 0;   // stored (recoverable) energy per unit reference length
  StrutLawState state; // trial history
};

class StrutLaw {
 public:
  static constexpr double kResidual = 0.2;        // r: residual strength over Pu
  static constexpr double kResidualStart = 5.0;   // s where the residual is reached, over s_p
  static constexpr double kResidualEnd = 8.0;     // s where the residual starts to fall, over s_p
  static constexpr double kGone = 10.0;           // s where the strut is gone, over s_p

  StrutLaw() = default;
  // Requires K > 0 and Pu > 0; throws std::invalid_argument otherwise.
  StrutLaw(double K, double Pu);

  double stiffness() const { return K_; }
  double strength() const { return Pu_; }
  double peakStrain() const { return Pu_ / K_; }
  // Keeps the share f (0 < f <= 1) of stiffness and strength (WEAKen): s_p unchanged.
  void scale(double f);

  // The compressive force of the envelope at shortening s >= 0 and its slope.
  double envelope(double s, double* slope = nullptr) const;
  // The response at strain eps from the committed history.
  StrutResponse evaluate(double eps, const StrutLawState& committed) const;

 private:
  double K_ = 1, Pu_ = 1;
};

}  // namespace c2d
