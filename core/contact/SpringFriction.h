#pragma once
// Coulomb friction along one coordinate x (the ground's horizontal position of
// a node, a node's position along a member it presses on) through a stick
// element: a spring k in parallel with a dashpot c (Kelvin-Voigt) on the
// stick stretch e = x - a, in series with a Coulomb slider at mu N (N >= 0 the
// normal force). The element's force F = k e + c de/dt pulls the point back;
// while |F| < mu N the anchor a stays (stick, de/dt = dx/dt), at |F| = mu N
// the point slides and the anchor follows (k e + c de/dt = mu N along the
// slip). Two consequences:
//   - the stretch never leaves [-L, L], L = mu N / k: the spring stores at
//     most (mu N)^2 / (2 k), so it can never give back more than that;
//   - the dashpot c answers a sudden slip speed v at once (c v), so that an
//     impact's Coulomb impulse mu int N dt is delivered even when the contact
//     lasts less than the spring takes to build mu N; at rest it carries
//     nothing (a sustained load is held by the spring without creep).
// c is 2 sqrt(k m), the stick element critically damped for the mass m the
// contact moves (frictionStickDamping): it stops the point without ringing,
// the same at every step. c = 0 gives the elastic-plastic spring law.
//
// Mid-point scheme: N is the step's, x moves along the straight path from x_n
// to x_n+1 at the step's mean speed, and the force is the element's work along
// that path (stick, then sliding, in closed form) divided by the increment:
// its work is the spring energy's change plus the dashpot's and the slider's
// dissipation, exactly. The force is continuously differentiable in x_n+1 but
// where a sliding point reverses. Newmark: the element's force at t_n+1 on the
// same path (the return mapping for c = 0). Statics: c = 0 (no rate).
namespace c2d {

struct SpringFrictionForce {
  double force = 0;    // on the point along x: -(k e + c de/dt) while sticking
  double dx = 0;       // d force / d x_n+1
  double dN = 0;       // d force / d N
  double anchor = 0;   // where the spring is anchored at the end of the step
  double slipped = 0;  // energy the dashpot and sliding dissipated over the step (>= 0)
};

// The stick element's dashpot (kN s/m) for the spring k and the mass m the
// contact moves: critical damping, 2 sqrt(k m); none for a point that does not
// move (m infinite) or has no mass.
double frictionStickDamping(double k, double m);

// The law over a step of length h (> 0 for a dynamic step; c is ignored
// otherwise) from x_n = xn to x_n+1 = x with the anchor a at t_n. N <= 0: the
// spring lets go (its energy is dissipated, the anchor follows x).
SpringFrictionForce springFriction(double k, double c, double mu, double N, double a, double xn,
                                   double x, double h, bool midPoint);

inline double springFrictionEnergy(double k, double stretch) { return 0.5 * k * stretch * stretch; }

}  // namespace c2d
