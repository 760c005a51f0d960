#pragma once
// The crushing law of a penalty contact with restitution e (GROUnd and MEMBers
// records): with p the penetration and q its largest value since the contact
// began (the loading point), the force is
//   f = k p                  for p >= q (loading: beyond the loading point),
//   f = (k / e^2)(p - p_s)   for p_s < p < q (unloading and reloading),
//   f = 0                    below the set p_s = q (1 - e^2).
// A body striking with speed v leaves with e v whatever its mass, speed and k.
// The loading work beyond q, k (p^2 - q^2)/2, is dissipated but for the share
// e^2 that the stiffer unloading branch stores: U = f^2 e^2 / (2 k). e = 1 is
// the elastic law k <p>^2 / 2.
namespace c2d {

struct CrushingLaw {
  double k = 0, ku = 0, q = 0, ps = 0;  // loading and unloading stiffness, loading point, set

  // The law of stiffness k and restitution e whose loading point is q.
  CrushingLaw(double k, double e, double q) : k(k), ku(k / (e * e)), q(q), ps(q * (1 - e * e)) {}

  double force(double p) const { return p >= q ? k * p : p > ps ? ku * (p - ps) : 0.0; }
  double slope(double p) const { return p >= q ? k : p > ps ? ku : 0.0; }
  // Energy stored at p (the law's loading point already max(q, p)).
  double energy(double p) const {
    const double f = force(p);
    return 0.5 * f * f / ku;
  }
  // The law's work on the straight path from p0 to p1 divided by p1 - p0 (a
  // discrete derivative of its energy, exact on every linear piece; closed
  // forms per branch for e = 1), and the derivative of that with respect to
  // p1. p0 != p1 unless both lie on one piece (then the mean of the end
  // forces).
  void midPoint(double p0, double p1, double& force, double& tangent) const;
  // Energy the law dissipates on the way from p0 to p1 (loading beyond
  // max(q, p0)): k (1 - e^2)(p1^2 - q0^2) / 2, >= 0.
  double dissipated(double p0, double p1) const;
};

// The stored energy of a contact whose loading point was q at the last commit,
// at penetration p (0 out of contact).
double crushingEnergy(double k, double e, double q, double p);
// The loading point after a step that ends at penetration p (0 out of contact).
inline double crushingLoadingPoint(double q, double p) { return p > 0 ? (p > q ? p : q) : 0.0; }

}  // namespace c2d
