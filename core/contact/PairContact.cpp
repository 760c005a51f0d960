// One node-segment pair of the member contact: its penetration (side, rounded
// ends, the held side of a ruptured joint's pair), the friction's coordinate
// along the segment, and the force and tangent of its law over a step (the
// model and the formulas: docs/design/member-contact.md).
#include "core/contact/PairContact.h"

#include <algorithm>
#include <cmath>

#include "core/contact/ContactDamper.h"
#include "core/contact/CrushingLaw.h"
#include "core/contact/SpringFriction.h"

namespace c2d {

namespace {

using Vec4 = Eigen::Matrix<double, 4, 1>;
using Mat4 = Eigen::Matrix<double, 4, 4>;
using Mat2 = Eigen::Matrix2d;

// Penetration, its gradient and Hessian with respect to z = (r1, r2),
// r1 = x - a, r2 = b - a.
struct Penetration {
  double p = 0;
  Vec4 g = Vec4::Zero();
  Mat4 H = Mat4::Zero();
};

Vec2 perp(const Vec2& v) { return Vec2(-v.y(), v.x()); }  // J v: v turned by +90 degrees

// The node's position along the segment, c = r1.r2 / |r2| (measured from a),
// its gradient and Hessian in z: the coordinate of the pair's friction.
void slipCoordinate(const Vec4& z, bool wantHessian, Penetration& out) {
  out.g.setZero();
  if (wantHessian) out.H.setZero();
  const Vec2 r1 = z.head<2>(), r2 = z.tail<2>();
  const double l2 = r2.squaredNorm();
  out.p = 0;
  if (l2 == 0) return;
  const double l = std::sqrt(l2), l3 = l2 * l;
  const double c = r1.dot(r2) / l;
  out.p = c;
  out.g.head<2>() = r2 / l;
  out.g.tail<2>() = r1 / l - c * r2 / l2;
  if (!wantHessian) return;
  const Mat2 h12 = Mat2::Identity() / l - r2 * r2.transpose() / l3;
  const Mat2 h22 = -(r1 * r2.transpose() + r2 * r1.transpose()) / l3 +
                   3 * c * r2 * r2.transpose() / (l2 * l2) - c * Mat2::Identity() / l2;
  out.H.topRightCorner<2, 2>() = h12;
  out.H.bottomLeftCorner<2, 2>() = h12.transpose();
  out.H.bottomRightCorner<2, 2>() = h22;
}

// Rounded end: p = h - |r| with r = r1 (end a, sign = 0) or r1 - r2 (end b).
void endPenetration(const Vec2& r, bool endB, double h, bool wantHessian, Penetration& out) {
  const double dist = r.norm();
  out.p = h - dist;
  if (dist == 0) return;  // the node on the end point itself: no direction
  const Vec2 e = r / dist;
  out.g.head<2>() = -e;
  out.g.tail<2>() = endB ? e : Vec2::Zero();
  if (!wantHessian) return;
  const Mat2 P = -(Mat2::Identity() - e * e.transpose()) / dist;
  out.H.topLeftCorner<2, 2>() = P;
  if (endB) {
    out.H.topRightCorner<2, 2>() = -P;
    out.H.bottomLeftCorner<2, 2>() = -P;
    out.H.bottomRightCorner<2, 2>() = P;
  }
}

// The side's penetration p = h - s d, d = (r2 x r1) / |r2| the signed
// distance from the segment's line.
void sidePenetration(const Vec4& z, int side, double h, bool wantHessian, Penetration& out) {
  const Vec2 r1 = z.head<2>(), r2 = z.tail<2>();
  const double l2 = r2.squaredNorm();
  const double l = std::sqrt(l2), l3 = l2 * l;
  const double c = r2.x() * r1.y() - r2.y() * r1.x();
  const double s = side;
  out.p = h - s * c / l;
  const Vec2 jr1 = perp(r1), jr2 = perp(r2);
  out.g.head<2>() = -s * jr2 / l;
  out.g.tail<2>() = -s * (-jr1 / l - c * r2 / l3);
  if (!wantHessian) return;
  Mat2 J;
  J << 0, -1, 1, 0;
  const Mat2 h12 = J / l - jr2 * r2.transpose() / l3;
  const Mat2 h22 = (jr1 * r2.transpose() + r2 * jr1.transpose()) / l3 - c * Mat2::Identity() / l3 +
                   3 * c * r2 * r2.transpose() / (l2 * l3);
  out.H.topRightCorner<2, 2>() = -s * h12;
  out.H.bottomLeftCorner<2, 2>() = -s * h12.transpose();
  out.H.bottomRightCorner<2, 2>() = -s * h22;
}

// A held node inside the span (the pieces of a ruptured joint): the end
// faces. The side's penetration alone let a node on the centre line slide
// into the span at p = h (about 0 with the whole distance offset): two pieces
// lying end to end and pressed together slid their tips past each other,
// each pushed only across the other's line, where the two held sides leave
// no position to go to, and ended crossed (the six-storey fall: 2-8 cm).
// Added to it, B(x), x the node's distance into the span from the nearer
// end: x^2 / (2 w) up to w, then x - w / 2, turning over another w to its
// cap W (w = kFaceRamp and W = the pair's full contact distance): B and its
// slope are zero at the end, so that the penetration stays continuous in
// value and slope with the held side's beyond the end; a held node then
// enters the span only as far from the line (on its side) as B, is pushed
// back out of it along the segment as well as across, and one clear of the
// line by the full distance is not pushed.
constexpr double kFaceRamp = 0.01;

void endFace(const Vec4& z, double face, bool wantHessian, Penetration& out) {
  const Vec2 r2 = z.tail<2>();
  const double l = r2.norm();
  if (l == 0) return;
  Penetration x;  // the distance into the span from the nearer end
  slipCoordinate(z, wantHessian, x);
  if (x.p > 0.5 * l) {  // from b: l - c
    x.p = l - x.p;
    x.g = -x.g;
    x.g.tail<2>() += r2 / l;
    if (wantHessian) {
      x.H = -x.H;
      x.H.bottomRightCorner<2, 2>() += (Mat2::Identity() - r2 * r2.transpose() / (l * l)) / l;
    }
  }
  const double w = kFaceRamp * face, cap = face;
  if (x.p <= 0 || w <= 0) return;
  double B, Bx, Bxx;  // B(x), B', B''
  if (x.p < w) {
    B = x.p * x.p / (2 * w), Bx = x.p / w, Bxx = 1 / w;
  } else if (x.p <= cap) {
    B = x.p - 0.5 * w, Bx = 1, Bxx = 0;
  } else if (x.p < cap + w) {
    const double y = x.p - cap;
    B = x.p - 0.5 * w - y * y / (2 * w), Bx = 1 - y / w, Bxx = -1 / w;
  } else {
    B = cap, Bx = 0, Bxx = 0;
  }
  out.p += B;
  out.g += Bx * x.g;
  if (wantHessian) out.H += Bx * x.H + Bxx * x.g * x.g.transpose();
}

void penetration(const Vec4& z, int side, double h, bool wantHessian, Penetration& out,
                 double face = 0) {
  out.g.setZero();
  if (wantHessian) out.H.setZero();
  const Vec2 r1 = z.head<2>(), r2 = z.tail<2>();
  const double l2 = r2.squaredNorm();
  if (l2 == 0) return endPenetration(r1, false, h, wantHessian, out);
  const double xi = r1.dot(r2) / l2;
  if (xi < 0 || xi > 1) {
    // A held node beyond an end on the wrong side: with rho its distance from
    // the end point and e its distance beyond the end along the segment,
    // p = h + rho - 2 e^2 / rho = h + (d^2 - e^2) / rho. It is the span's
    // h + |d| where e = 0 (value and slope), and the rounded end's h - rho
    // where the node crosses the line beyond the end (d = 0: value and slope
    // again), so that a node held end to end with the member (a ruptured
    // joint's pieces in line) meets no kink in its force there.
    if (face > 0 && side * (r2.x() * r1.y() - r2.y() * r1.x()) < 0) {
      const Vec2 r = xi < 0 ? r1 : Vec2(r1 - r2);
      Penetration end;  // -rho, -grad rho, -Hess rho
      endPenetration(r, xi > 1, 0.0, wantHessian, end);
      const double rho = -end.p;
      if (rho == 0) return endPenetration(r, xi > 1, h, wantHessian, out);
      Penetration e;
      slipCoordinate(z, wantHessian, e);  // c, measured from a
      if (xi > 1) {                       // e = c - l
        const double l = std::sqrt(l2);
        e.p -= l;
        e.g.tail<2>() -= r2 / l;
        if (wantHessian)
          e.H.bottomRightCorner<2, 2>() -= (Mat2::Identity() - r2 * r2.transpose() / l2) / l;
      } else {  // e = -c
        e.p = -e.p;
        e.g = -e.g;
        if (wantHessian) e.H = -e.H;
      }
      const double ee = e.p, a = 2 * ee * ee / (rho * rho), b = 4 * ee / rho;
      const Vec4 gr = -end.g;
      out.p = h + rho - 2 * ee * ee / rho;
      out.g = (1 + a) * gr - b * e.g;
      if (wantHessian) {
        const Vec4 da = (b / rho) * e.g - (2 * a / rho) * gr;  // grad a
        const Vec4 db = (4 / rho) * e.g - (b / rho) * gr;      // grad b
        out.H = -(1 + a) * end.H + gr * da.transpose() - b * e.H - e.g * db.transpose();
      }
      return;
    }
    return xi < 0 ? endPenetration(r1, false, h, wantHessian, out)
                  : endPenetration(r1 - r2, true, h, wantHessian, out);
  }
  sidePenetration(z, side, h, wantHessian, out);
  if (face > 0) endFace(z, face, wantHessian, out);
}

Vec4 relative(const PairPositions& q) {
  Vec4 z;
  z << q.x - q.a, q.b - q.a;
  return z;
}

// Force and tangent in z to the node and segment translations (x, a, b):
// r1 = x - a, r2 = b - a.
void toPair(const Vec4& fz, const Mat4* kz, PairVec& f, PairMat* k) {
  f.segment<2>(0) = fz.head<2>();
  f.segment<2>(2) = -fz.head<2>() - fz.tail<2>();
  f.segment<2>(4) = fz.tail<2>();
  if (!kz) return;
  Eigen::Matrix<double, 4, 6> B = Eigen::Matrix<double, 4, 6>::Zero();
  B.block<2, 2>(0, 0).setIdentity();
  B.block<2, 2>(0, 2) = -Mat2::Identity();
  B.block<2, 2>(2, 2) = -Mat2::Identity();
  B.block<2, 2>(2, 4).setIdentity();
  *k = B.transpose() * (*kz) * B;
}

}  // namespace

int pairSide(const PairPositions& q) {
  const Vec2 r1 = q.x - q.a, r2 = q.b - q.a;
  return r2.x() * r1.y() - r2.y() * r1.x() >= 0 ? 1 : -1;
}

double pairPenetration(const PairPositions& q, int side, double h, double face) {
  Penetration p;
  penetration(relative(q), side, h, false, p, face);
  return p.p;
}

double pairPenetrationRate(const PairPositions& q, const PairPositions& v, int side, double h,
                           double face) {
  Penetration p;
  penetration(relative(q), side, h, false, p, face);
  return p.g.dot(relative(v));
}

namespace {

// The discrete gradient (Gonzalez) of a function f of z between z0 and z1:
// D = grad f(z_m) + (f1 - f0 - grad f(z_m).dz) dz / |dz|^2, so that D.dz = f1 - f0,
// and, times w, its derivative with respect to z1 (wdD). em: f at z_m with its
// Hessian; g1: grad f(z1). Below a relative step of 1e-7 the correction,
// O(|dz|^2), is left out: there its round-off (eps |z| / |dz|) would exceed it.
Vec4 discreteGradient(const Vec4& z0, const Vec4& z1, double f0, double f1, const Penetration& em,
                      const Vec4& g1, double scale, double w, Mat4* wdD) {
  const Vec4 dz = z1 - z0;
  const double n2 = dz.squaredNorm();
  const bool corrected = n2 > 1e-14 * scale * scale;
  Vec4 D = em.g;
  double c = 0;
  if (corrected) {
    c = (f1 - f0 - em.g.dot(dz)) / n2;
    D += c * dz;
  }
  if (wdD) {
    *wdD = 0.5 * w * em.H;
    if (corrected) {
      const Vec4 dc = (g1 - em.g - 0.5 * em.H * dz) / n2 - 2 * c * dz / n2;
      *wdD += w * (c * Mat4::Identity() + dz * dc.transpose());
    }
  }
  return D;
}

}  // namespace

bool pairTouches(const PairPositions& q0, const PairPositions& q1, int side, double h,
                 const StepRule& rule, bool wantTangent, PairStep& step, double face) {
  pairStart(q0, side, h, step, face);
  return pairTouches(q1, side, h, rule, wantTangent, step, face);
}

void pairStart(const PairPositions& q0, int side, double h, PairStep& step, double face) {
  step.z0 = relative(q0);
  Penetration e0;
  penetration(step.z0, side, h, false, e0, face);
  step.p0 = e0.p;
}

bool pairTouches(const PairPositions& q1, int side, double h, const StepRule& rule,
                 bool wantTangent, PairStep& step, double face) {
  const bool midPoint = rule.scheme == Scheme::MidPoint;
  step.z1 = relative(q1);
  Penetration e1;
  penetration(step.z1, side, h, wantTangent && !midPoint, e1, face);
  step.p1 = e1.p;
  step.g1 = e1.g;
  // The Hessian at t_n+1 only where the force law reads it (static, Newmark).
  if (wantTangent && !midPoint) step.H1 = e1.H;
  return midPoint ? (step.p0 > 0 || step.p1 > 0) : step.p1 > 0;
}

bool pairContact(const PairPositions& q0, const PairPositions& q1, int side, double h,
                 const PairLaw& law, const StepRule& rule, bool wantTangent, PairVec& force,
                 PairMat& tangent, PairOutcome* outcome, double face) {
  PairStep step;
  if (!pairTouches(q0, q1, side, h, rule, wantTangent, step, face)) {
    // Out of contact over the step: no force, and the friction spring lets go.
    if (outcome)
      *outcome = PairOutcome{step.p0, step.p1, 0.0, springFrictionEnergy(law.k, law.stretch)};
    return false;
  }
  pairContact(step, side, h, law, rule, wantTangent, force, tangent, outcome, face);
  return true;
}

namespace {

// Newmark's dashpot c r dp/dt at t_n+1: r its ramp (cr = c r), r1 = dp/dt,
// and d(c r dp/dt)/dz1.
struct NewmarkDashpot {
  bool on = false;
  double cr = 0, r1 = 0;
  Vec4 dDamper = Vec4::Zero();
};

// Newmark's dashpot c r dp/dt ramps in over the step's motion beyond the set
// as the ground's does (ContactDamper: r from 0 where the pair begins or
// ends touching, so that the force is continuous there).
NewmarkDashpot newmarkDashpot(const PairStep& step, const Penetration& e1, const PairLaw& law,
                              const StepRule& rule, double ps, bool damped) {
  const bool midPoint = rule.scheme == Scheme::MidPoint;
  NewmarkDashpot d;
  d.on = damped && !midPoint && step.p1 > ps;
  const DamperRamp ramp = d.on ? damperRamp(ps, step.p0, step.p1) : DamperRamp{};
  d.cr = law.c * ramp.w;
  const Vec4 rate1 =
      d.on ? Vec4(rule.velocity(Vec4(step.z1 - step.z0), law.zv, law.za)) : Vec4(Vec4::Zero());
  d.r1 = e1.g.dot(rate1);  // dp/dt at t_n+1
  d.dDamper = d.on ? Vec4(d.cr * (rule.cv * e1.g + e1.H * rate1) + law.c * ramp.slope * d.r1 * e1.g)
                   : Vec4(Vec4::Zero());
  return d;
}

// The normal force fz on z and its derivative kz w.r.t. z1: w along grad p
// at t_n+1 (with Newmark's dashpot), or along the discrete gradient D
// (mid-point).
void normalForce(const PairStep& step, const Penetration& e1, int side, double h, double face,
                 double scale, double w, double dw, const NewmarkDashpot& dashpot,
                 bool midPoint, bool wantTangent, Vec4& fz, Mat4& kz) {
  if (!midPoint) {
    fz = w * e1.g;
    if (wantTangent) kz = dw * e1.g * e1.g.transpose() + w * e1.H;
    if (dashpot.on) {
      fz += dashpot.cr * dashpot.r1 * e1.g;
      if (wantTangent) kz += e1.g * dashpot.dDamper.transpose() + dashpot.cr * dashpot.r1 * e1.H;
    }
  } else {
    Mat4 wdD;
    Penetration em;
    penetration(0.5 * (step.z0 + step.z1), side, h, wantTangent, em, face);
    const Vec4 D = discreteGradient(step.z0, step.z1, step.p0, step.p1, em, e1.g, scale, w,
                                    wantTangent ? &wdD : nullptr);
    fz = w * D;
    if (wantTangent) kz = D * (dw * e1.g).transpose() + wdD;
  }
}

// Friction along the segment: the spring law on the slip coordinate c, its
// force F = -f on c (an internal force, as the penalty's) through the
// coordinate's gradient (discrete gradient under the mid-point scheme).
void addFriction(const PairStep& step, const PairLaw& law, const StepRule& rule, double N,
                 const Vec4& dNdz, double scale, bool wantTangent, Vec4& fz, Mat4& kz,
                 PairOutcome* outcome) {
  const Vec4& z0 = step.z0;
  const Vec4& z1 = step.z1;
  const bool midPoint = rule.scheme == Scheme::MidPoint;
  Penetration c0, c1;
  slipCoordinate(z0, false, c0);
  slipCoordinate(z1, wantTangent && !midPoint, c1);
  const SpringFrictionForce fr = springFriction(law.k, law.stick, law.mu, N, c0.p - law.stretch,
                                                c0.p, c1.p, rule.dynamic() ? rule.h : 0.0, midPoint);
  const double F = -fr.force;
  if (outcome) {
    outcome->stretch = c1.p - fr.anchor;
    outcome->slipped = fr.slipped;
  }
  const Vec4 dF = -fr.dx * c1.g - fr.dN * dNdz;  // dF/dz1
  if (!midPoint) {
    fz += F * c1.g;
    if (wantTangent) kz += c1.g * dF.transpose() + F * c1.H;
  } else {
    Mat4 wdD;
    Penetration cm;
    slipCoordinate(0.5 * (z0 + z1), wantTangent, cm);
    const Vec4 Dc =
        discreteGradient(z0, z1, c0.p, c1.p, cm, c1.g, scale, F, wantTangent ? &wdD : nullptr);
    fz += F * Dc;
    if (wantTangent) kz += Dc * dF.transpose() + wdD;
  }
}

}  // namespace

void pairContact(const PairStep& step, int side, double h, const PairLaw& law, const StepRule& rule,
                 bool wantTangent, PairVec& force, PairMat& tangent, PairOutcome* outcome,
                 double face) {
  const Vec4& z0 = step.z0;
  const Vec4& z1 = step.z1;
  const double k = law.k;
  const bool midPoint = rule.scheme == Scheme::MidPoint;
  const bool rubs = law.mu > 0;
  Penetration e1;
  e1.p = step.p1;
  e1.g = step.g1;
  if (wantTangent && !midPoint) e1.H = step.H1;
  const double p0 = step.p0, p1 = step.p1;
  if (outcome) *outcome = PairOutcome{p0, p1, 0.0, 0.0};
  // The normal law: w, its derivative dw w.r.t. p1, and the normal force N
  // (without the dissipative term) with dN/dp1.
  double w = 0, dw = 0;
  const CrushingLaw normal(k, law.restitution, std::max(law.q, p0));
  if (!midPoint) {
    w = normal.force(p1);
    dw = normal.slope(p1);
  } else {
    normal.midPoint(p0, p1, w, dw);  // phi'(p0, p1): the law's discrete derivative
  }
  // The dashpot: along D with the penalty (mid-point), along grad p at t_n+1
  // with the rate dp/dt = grad p . dz/dt there (Newmark, below).
  const bool damped = law.c > 0 && rule.dynamic();
  if (damped && midPoint) {
    const DamperForce f = damperForce(law.c, normal.ps, p0, p1, 0.0, 0.0, rule);
    w += f.force;
    dw += f.slope;
  }
  // Friction's N: the whole normal force while it pushes (the dashpot's too),
  // and dN/dz1.
  const NewmarkDashpot dashpot = newmarkDashpot(step, e1, law, rule, normal.ps, damped);
  const double w1 = w + dashpot.cr * dashpot.r1;
  const double N = std::max(w1, 0.0);
  Vec4 dNdz = Vec4::Zero();
  if (rubs && w1 > 0 && wantTangent) dNdz = dw * e1.g + dashpot.dDamper;
  const double scale = z0.norm() + z1.norm() + h;
  Vec4 fz;
  Mat4 kz;
  normalForce(step, e1, side, h, face, scale, w, dw, dashpot, midPoint, wantTangent, fz, kz);
  if (rubs) addFriction(step, law, rule, N, dNdz, scale, wantTangent, fz, kz, outcome);
  toPair(fz, wantTangent ? &kz : nullptr, force, wantTangent ? &tangent : nullptr);
}

}  // namespace c2d
