#include "solvers/TimeIntegrator.h"

#include <cstdio>

namespace c2d {

TimeIntegrator TimeIntegrator::newmark(double beta, double gamma) {
  TimeIntegrator t;
  t.kind = Kind::Newmark;
  t.beta = beta;
  t.gamma = gamma;
  return t;
}

TimeIntegrator TimeIntegrator::midPoint(double alpha, double beta) {
  TimeIntegrator t;
  t.kind = Kind::MidPoint;
  t.alpha = alpha;
  t.betaV = beta;
  return t;
}

StepRule TimeIntegrator::rule(double dt) const {
  StepRule r;
  switch (kind) {
    case Kind::Static:
      r.scheme = Scheme::Static;
      break;
    case Kind::Newmark:
      r.scheme = Scheme::Newmark;
      r.h = dt;
      r.ca = 1.0 / (beta * dt * dt);
      r.av = -1.0 / (beta * dt);
      r.aa = -(0.5 / beta - 1.0);
      r.cv = gamma / (beta * dt);
      r.vv = 1.0 - gamma / beta;
      r.va = dt * (1.0 - 0.5 * gamma / beta);
      break;
    case Kind::MidPoint: {
      r.scheme = Scheme::MidPoint;
      r.alpha = alpha;
      r.beta = betaV;
      r.h = dt;
      const double w = 0.5 + betaV;
      r.cv = 1.0 / (w * dt);
      r.vv = -(0.5 - betaV) / w;
      r.va = 0;
      // a_eff = (v_n+1 - v_n)/dt
      r.ca = r.cv / dt;
      r.av = (r.vv - 1.0) / dt;
      r.aa = 0;
      break;
    }
  }
  return r;
}

std::string TimeIntegrator::describe() const {
  char buf[128];
  switch (kind) {
    case Kind::Static:
      return "static";
    case Kind::Newmark:
      std::snprintf(buf, sizeof buf, "Newmark (beta = %g, gamma = %g)", beta, gamma);
      return buf;
    case Kind::MidPoint:
      std::snprintf(buf, sizeof buf, "energy %s mid-point (alpha = %g, beta = %g)",
                    alpha == 0 && betaV == 0 ? "conserving" : "decaying", alpha, betaV);
      return buf;
  }
  return {};
}

}  // namespace c2d
