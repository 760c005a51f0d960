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

// The loading point, in [p, q], at which a contact at penetration p stores
// `extra` more than at q (q > p: on the unloading branch or in the set): a
// lower loading point, a smaller set and a stiffer push back. At most what
// the law can store at p (the loading point p, U = e^2 k p^2 / 2). q itself
// for e = 1 (the elastic law stores k p^2 / 2 whatever q) or p <= 0.
double crushingRaised(double k, double e, double q, double p, double extra);

// The peak of an impact whose turn fell inside a step: the loading point from
// which a mass m, unloading along the law (stiffness k, restitution e < 1),
// comes back to the penetration p > 0 at the rate r = dp/dt < 0. On the
// unloading branch, m r^2 / 2 + (k / e^2)(p - (1 - e^2) q)^2 / 2 = e^2 k q^2 / 2
// (the energy the branch gives back); when p lies in the set (the mass has
// left the crushed surface), m r^2 / 2 = e^2 k q^2 / 2. p itself for m = 0 or
// r = 0, and q grows with m r^2.
double crushingPeak(double k, double e, double m, double p, double r);

// The loading point after a step from penetration p0 to p1 at the rates r0
// (t_n) and r1 (t_n+1), for the contact's mass m: the largest penetration at
// the steps' ends, and when the contact turned back within the step (r0 > 0 >
// r1, in contact at its end) the peak the mass came back from
// (crushingPeak) if that is deeper. The steps' ends alone miss the peak by a
// share that grows with the step (a 10.2 t mass striking k = 1e5 at 16 m/s in
// steps of 0.01 s left at 0.39 v for e = 0.3): with it a mass leaves with e v
// under the mid-point scheme whatever the step, as long as the turn ends in
// contact (solvers/ImpactSteps.h shortens the steps that do not). The
// stored energy this takes from the contact, U(p1; q) - U(p1; peak) >= 0, is
// dissipated at the commit.
double crushingLoadingPoint(double k, double e, double q, double m, double p1, double r0,
                            double r1);

}  // namespace c2d
