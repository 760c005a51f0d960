#pragma once
// The concrete of an RC section as a plane shape (SECTion RECTangular, TEE,
// CIRCular, ANNUlar): its gross area, centroid and second moment, its width
// at a depth, the widths and depths the shear rule reads, and the resultant of
// the EC2 parabola-rectangle stress over it for a strain plane. RcSection
// (materials/RcSection.h) takes every geometric quantity from here.
//
// The shape is a sum of parts, each integrated in closed form or exactly:
//  - rectangles (strips of constant width between two depths: RECTangular one,
//    TEE two, the flange beff x hf over the web bw x (h - hf)): the stress is
//    a polynomial of degree 2 in the depth on each piece between the plane's
//    kinks (strain 0 and -eps_c2), so two Gauss points per piece are exact;
//  - disks (CIRCular one, ANNUlar the outer disk less the inner one): with the
//    depth z = zc - r cos(phi) the chord width is 2 r sin(phi), and on each
//    piece between the kinks the stress is a polynomial in cos(phi): the
//    integrals of cos^k(phi) sin^2(phi), k <= 3, are taken in closed form.
//
// Depths z from the compressed face of the sign (sign +1: the top face as
// given; -1: the shape turned upside down), strains e0 + kappa z, tension
// positive, N > 0 in tension; moments about the gross centroid of the concrete
// (mid-depth of rectangles and circles; the member's axis), positive when they
// compress the face at z = 0. Lengths in the deck's unit, no units of its own.
#include <vector>

#include "core/MaterialSet.h"

namespace c2d {

class SectionShape {
 public:
  // Throws std::invalid_argument for sizes that make no shape (b, h, D not
  // positive; TEE: beff < bw or hf outside (0, h); ANNUlar: t outside (0, D/2)).
  explicit SectionShape(const RcSectionData& d);

  SectionShapeKind kind() const { return kind_; }
  double depth() const { return h_; }
  double area() const { return area_; }
  // Depth of the gross centroid from the compressed face of the sign.
  double centroidDepth(int sign) const { return sign > 0 ? zg_ : h_ - zg_; }
  // Gross second moment about the centroid.
  double secondMoment() const { return i_; }
  // Width of the concrete at depth z from the compressed face of the sign.
  double width(double z, int sign) const;

  // Shear (read by RcSection::shearCapacity): the web width bw and the
  // effective depth d. RECTangular b, TEE bw, with d the depth of the
  // farthest bars (given); CIRCular bw = D and ANNUlar bw = 2t (the two
  // walls parallel to the shear), d = 0.8 D for both (ACI 318-19 22.5.2.2).
  double webWidth() const;
  double effectiveDepth(double farthestBars) const;
  // Shear area for GA, shearFactor(nu) shearWidth() h: 5/6 of the (web's)
  // rectangle b h; circles Cowper's (1966) factor of the solid or hollow
  // circle at Poisson's ratio nu times A (shearWidth = A/h).
  double shearFactor(double nu) const;
  double shearWidth() const;
  double shearArea(double nu) const { return shearFactor(nu) * shearWidth() * h_; }

  // The parabola-rectangle of EC2 3.1.7 (n = 2): sigma(e) = fc (2x + x^2),
  // x = e/eps_c2, for -eps_c2 < e < 0; -fc beyond; 0 in tension.
  static double parabolaRectangle(double e, double fc, double epsC2);
  struct Resultant {
    double N = 0, M = 0;
  };
  // The concrete's resultant for the plane e(z) = e0 + kappa z (sign's frame).
  Resultant concrete(double e0, double kappa, int sign, double fc, double epsC2) const;

 private:
  struct Strip {
    double z0 = 0, z1 = 0, w = 0;
  };
  struct Disk {
    double zc = 0, r = 0, s = 1;  // s = -1: a hole
  };
  Resultant strip(const Strip& p, double e0, double kappa, double zg, double fc,
                  double epsC2) const;
  Resultant disk(const Disk& p, double e0, double kappa, double zg, double fc, double epsC2) const;

  SectionShapeKind kind_;
  double h_ = 0, web_ = 0, wall_ = 0;
  std::vector<Strip> strips_;  // in the frame of sign +1
  std::vector<Disk> disks_;
  double area_ = 0, zg_ = 0, i_ = 0;
};

}  // namespace c2d
