#pragma once
// Elastic-plastic Coulomb friction along one coordinate x (the ground's
// horizontal position of a node, a node's position along a member it presses
// on): a spring of stiffness k anchored at a, sliding when its force reaches
// mu N (N >= 0 the normal force), the anchor then following at mu N / k. It
// sticks to within mu N / k and never creeps; the spring stores
// k (x - a)^2 / 2 <= (mu N)^2 / (2 k); sliding dissipates mu N per unit of slip.
//
// Mid-point scheme: the force is the law's work along the straight path from
// x_n to x_n+1 (elastic, then sliding) divided by the step, so that its work is
// the spring energy's change plus what sliding dissipated; continuously
// differentiable in x_n+1 but where a sliding point reverses. Otherwise the
// law at t_n+1 (return mapping).
namespace c2d {

struct SpringFrictionForce {
  double force = 0;    // on the point along x: -k (x - a) while sticking
  double dx = 0;       // d force / d x_n+1
  double dN = 0;       // d force / d N
  double anchor = 0;   // where the spring is anchored at the end of the step
  double slipped = 0;  // energy sliding dissipated over the step (>= 0)
};

// N <= 0: the spring lets go (its energy is dissipated, the anchor follows x).
SpringFrictionForce springFriction(double k, double mu, double N, double a, double xn, double x,
                                   bool midPoint);

inline double springFrictionEnergy(double k, double stretch) { return 0.5 * k * stretch * stretch; }

}  // namespace c2d
