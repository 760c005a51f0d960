#include "macro/mesh/SectionEcho.h"

#include <cstdio>
#include <iomanip>
#include <sstream>
#include <string>

#include "materials/Confinement.h"
#include "materials/HingeLength.h"
#include "materials/RcSection.h"
#include "materials/SectionShape.h"
#include "materials/ShearResistance.h"

namespace c2d {

void echoLine(std::ostream& os, const std::string& name, double v) {
  os << "      " << std::left << std::setw(19) << name << std::right << std::setw(13)
     << std::scientific << std::setprecision(4) << v << "\n";
}

namespace {

void echoShape(std::ostream& os, const SectionShape& shape, const RcSectionData& d) {
  switch (d.shape) {
    case SectionShapeKind::Rectangle:
      echoLine(os, "Width b", d.b);
      echoLine(os, "Depth h", d.h);
      break;
    case SectionShapeKind::Tee:
      os << "      T-section (the flange at the top face)\n";
      echoLine(os, "Web width bw", d.b);
      echoLine(os, "Depth h", d.h);
      echoLine(os, "Flange width beff", d.flangeWidth);
      echoLine(os, "Flange thickness hf", d.flangeDepth);
      break;
    case SectionShapeKind::Circle:
      os << "      Circular section\n";
      echoLine(os, "Diameter D", d.h);
      break;
    case SectionShapeKind::Annulus:
      os << "      Annular section\n";
      echoLine(os, "Diameter D", d.h);
      echoLine(os, "Wall t", d.wall);
      break;
  }
  echoLine(os, "Concrete area", shape.area());
  echoLine(os, "Centroid from top", shape.centroidDepth(1));
  echoLine(os, "Gross I", shape.secondMoment());
  echoLine(os, "Shear area (nu 0.2)", shape.shearArea(RcSection::kConcretePoisson));
}

// The concrete's and the bars' data, and the bar layers.
void echoMaterials(std::ostream& os, const RcSection& rc, const RcSectionData& d) {
  echoLine(os, "Concrete fc", d.fc);
  echoLine(os, "Ec = 2 fc/eps_c2", rc.Ec());
  echoLine(os, "fct = fc/10", rc.fct());
  echoLine(os, "Bars fy", d.fy);
  echoLine(os, "Bars Es", d.Es);
  echoLine(os, "Bars fu", d.fu);
  echoLine(os, "Bars eu", d.eu);
  for (const RebarLayer& l : d.bars) {
    std::ostringstream s;
    s << std::scientific << std::setprecision(4) << "      Bar layer: depth " << l.depth
      << ", area " << l.area << "\n";
    os << s.str();
  }
}

// The transformed uncracked section and its axial capacities.
void echoTransformed(std::ostream& os, const RcSection& rc) {
  os << "      Transformed uncracked section (the concrete, bars (Es/Ec - 1) A):\n";
  echoLine(os, "EA", rc.EA());
  echoLine(os, "GA (nu 0.2)", rc.GA());
  echoLine(os, "EI", rc.EI());
  echoLine(os, "Centroid depth", rc.centroidDepth());
  echoLine(os, "Tension yield Nt", rc.tensionYield());
  echoLine(os, "Tension Ntu", rc.tensionUltimate());
  echoLine(os, "Squash load Nc", rc.squashLoad());
}

// The moment law at N = 0 in one sense (+: top face compressed): cracking,
// yield, ultimate, hardening, the hinge's rotation capacity, the balance point.
void echoMoments(std::ostream& os, const RcSection& rc, const RcSectionData& d, int sign) {
  const char* tag = sign > 0 ? "+" : "-";
  os << "      Moments "
     << (sign > 0 ? "positive (top face compressed)" : "negative (bottom face compressed)")
     << " at N = 0:\n";
  const RcSection::State y = rc.firstYield(0, sign), u = rc.ultimate(0, sign);
  const MomentLaw l = rc.at(sign, 0);
  echoLine(os, std::string("Mc") + tag + " (fct)", l.Mc);
  echoLine(os, std::string("My") + tag + " (first yield)", l.My);
  echoLine(os, std::string("kappa_y") + tag, y.kappa);
  echoLine(os, std::string("x_y") + tag, y.depth);
  echoLine(os, std::string("Mu") + tag + " (eps_cu2)", l.Mu);
  echoLine(os, std::string("kappa_u") + tag, u.kappa);
  echoLine(os, std::string("x_u") + tag, u.depth);
  echoLine(os, std::string("Kh1") + tag, l.Kh1);
  echoLine(os, std::string("Kh2") + tag, l.Kh2);
  echoLine(os, std::string("kappa_uc") + tag + " (eps_cu,c)", rc.ultimateConfined(0, sign).kappa);
  echoLine(os, std::string("Lpl - L_V/30") + tag, rc.hingeLengthBase(sign));
  echoLine(os, std::string("dbL") + tag + " (estimate)", tensionBarDiameter(d, rc.shape(), sign));
  const double lv = rc.referenceSpan();
  echoLine(os, std::string("theta_pl") + tag + " (L_V=4h)", rc.plasticRotation(0, sign, lv));
  echoLine(os, std::string("xiF") + tag + " (L_V=4h)", l.xiF);
  echoLine(os, std::string("Ks") + tag, -l.Mu / l.xiF);
  const RcSection::State b = rc.balance(sign);
  echoLine(os, std::string("Balance N") + tag, rc.forces(b.e0, b.kappa, sign).N);
  echoLine(os, std::string("Balance M") + tag, b.M);
}

// The shear resistance at N = 0 in both senses, and the shortest piece.
void echoShear(std::ostream& os, const RcSection& rc) {
  os << "      Shear (EC2 6.2.2, 6.2.3; Vu = max(VRd,c, VRd,s), see --help STIRrups):\n";
  for (int sign : {1, -1}) {
    const char* tag = sign > 0 ? "+" : "-";
    const ShearResistance::Parts p = rc.shear().parts(0.0, sign);
    echoLine(os, std::string("VRd,c") + tag, p.concrete);
    echoLine(os, std::string("VRd,s") + tag, p.stirrups);
    echoLine(os, std::string("cot theta") + tag, p.cot);
    echoLine(os, std::string("Vu") + tag, p.vu);
  }
  echoLine(os, "Shortest piece Lb", rc.shortestPiece());
}

// The stirrups and the core they confine.
void echoStirrups(std::ostream& os, const RcSection& rc, const RcSectionData& d) {
  const auto& st = d.stirrups;
  if (!st) return;
  echoLine(os, "Stirrups Asw", st->area);
  echoLine(os, "Stirrups s", st->spacing);
  echoLine(os, "Stirrups fyw", st->fy);
  if (const auto c = confinementOf(d)) {
    os << "      Confined core (EN 1998-3 A.3.2.2: alpha = (1 - s/2b0)(1 - s/2h0)(1 - sum bi^2/6b0h0),\n"
          "      corner bars only; fcc = fc (1 + 3.7 (alpha rho_sx fyw/fc)^0.86) (A.11);\n"
          "      eps_cu,c = 0.004 + 0.5 alpha rho_sx fyw/fcc (A.12); kappa_uc with fcc\n"
          "      and eps_c2,c = eps_c2 (fcc/fc)^2, EC2 (3.26)):\n";
    echoLine(os, "Core b0", c->b0);
    echoLine(os, "Core h0", c->h0);
    echoLine(os, "alpha", c->alpha);
    echoLine(os, "rho_sx = Asw/(b s)", c->rhoSx);
    echoLine(os, "fcc", c->fcc);
    echoLine(os, "eps_cu,c", rc.confinedStrain());
  }
}

// The interaction table: N from the squash load to the tension yield.
void echoInteraction(std::ostream& os, const RcSection& rc) {
  os << "      Interaction (N, Mu+, Mu-, My+, My-, Vu):\n";
  const double lo = -rc.squashLoad(), hi = rc.tensionYield();
  for (int i = 0; i <= 10; ++i) {
    const double n = lo + (hi - lo) * i / 10;
    const MomentLaw p = rc.at(1, n), q = rc.at(-1, n);
    char buf[160];
    std::snprintf(buf, sizeof buf, "      %13.4e %13.4e %13.4e %13.4e %13.4e %13.4e\n", n, p.Mu,
                  q.Mu, p.My, q.My, rc.shearCapacity(n));
    os << buf;
  }
}

}  // namespace

void echoSection(std::ostream& os, const MaterialSet& m) {
  const RcSection& rc = *m.rc;
  const RcSectionData& d = rc.data();
  os << "      RC section (EC2 parabola-rectangle, eps_c2 = 0.002, eps_cu2 = 0.0035; bars\n"
        "      elastic-perfectly plastic; moments about the concrete's centroid, positive\n"
        "      compressing the top)\n";
  echoShape(os, rc.shape(), d);
  echoMaterials(os, rc, d);
  echoTransformed(os, rc);
  for (int sign : {1, -1}) echoMoments(os, rc, d, sign);
  if (m.softening && m.softening->thetaR)
    echoLine(os, "Rupture thetaR", *m.softening->thetaR);
  os << "      Hinge length (EN 1998-3 (A.9), (A.10)): Lpl = L_V/30 + 0.2 h + 0.11 dbL fy/sqrt(fc),\n"
        "      theta_pl = (kappa_uc - kappa_y) Lpl (1 - 0.5 Lpl/L_V), xiF = 5 theta_pl; L_V = M/V of\n"
        "      the element at the hinge's opening (the log's hinge lines), within [h, 10 h]\n";
  echoShear(os, rc);
  echoStirrups(os, rc, d);
  for (int sign : {1, -1})
    if (const auto f = chordRotationFactor(d, 0, sign))
      echoLine(os, std::string("theta_um/(Lv/h)^.35") + (sign > 0 ? "+" : "-"), *f);
  echoInteraction(os, rc);
}

}  // namespace c2d
