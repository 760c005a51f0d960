#include "macro/mesh/SectionRecords.h"

#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "macro/mesh/SectionEcho.h"
#include "macro/mesh/SectionShapeRecords.h"
#include "macro/mesh/SubRecordFields.h"
#include "materials/Confinement.h"
#include "materials/HingedBending.h"
#include "materials/RcSection.h"
#include "materials/SectionLaws.h"
#include "materials/SectionShape.h"

namespace c2d {

using meshspec::expr;
using meshspec::failAt;
using meshspec::subSpec;
using meshspec::text;

namespace {

std::string str(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

void bindHardening(MeshContext& ctx, const Record& r, const CommandSpec& s, MaterialSet& mat,
                   LawRecords& seen) {
  const bool negative = keywordMatches(r.text(1), "NEGAtive");
  const std::string syntax =
      negative ? "HARDening NEGAtive Mc My Kh1 Kh2" : "HARDening BILInear Mc My Kh1 Kh2";
  subrecord::requireText(r, s.name, syntax);
  if (!negative && !keywordMatches(r.text(1), "BILInear"))
    failAt(r, 1, "expected BILInear (or NEGAtive: the values of negative moments)",
           "write " + syntax);
  const auto v = subrecord::values(ctx, r, s.name, 4, 4, syntax);
  if (v[0] <= 0) failAt(r, 2, "Mc must be positive");
  if (v[1] < v[0]) failAt(r, 3, "My must not be below Mc");
  if (v[2] <= 0) failAt(r, 4, "Kh1 must be positive");
  if (v[3] < 0) failAt(r, 5, "Kh2 must not be negative");
  const HardeningValues h{v[0], v[1], v[2], v[3]};
  if (negative) {
    seen.hardeningNeg = &r;
    if (!mat.hardening) mat.hardening = HardeningData{};
    mat.hardening->negative = h;
  } else {
    seen.hardening = &r;
    auto neg = mat.hardening ? mat.hardening->negative : std::nullopt;
    mat.hardening = HardeningData{};
    static_cast<HardeningValues&>(*mat.hardening) = h;
    mat.hardening->negative = neg;
  }
}

void bindSoftening(MeshContext& ctx, const Record& r, const CommandSpec& s, MaterialSet& mat,
                   LawRecords& seen) {
  const bool negative = keywordMatches(r.text(1), "NEGAtive");
  const std::string syntax =
      negative ? "SOFTening NEGAtive Mu Ks" : "SOFTening LINEar Mu Ks [thetaR [Mr [Lb]]]";
  subrecord::requireText(r, s.name, syntax);
  if (!negative && !keywordMatches(r.text(1), "LINEar"))
    failAt(r, 1, "expected LINEar (or NEGAtive: the values of negative moments)",
           "write " + syntax);
  const auto v = subrecord::values(ctx, r, s.name, negative ? 2 : 5, 2, syntax);
  if (v[0] <= 0) failAt(r, 2, "Mu must be positive");
  if (v[1] >= 0) failAt(r, 3, "Ks must be negative (softening)");
  if (negative) {
    seen.softeningNeg = &r;
    if (!mat.softening) mat.softening = SofteningData{};
    mat.softening->negative = std::make_pair(v[0], v[1]);
    return;
  }
  seen.softening = &r;
  auto neg = mat.softening ? mat.softening->negative : std::nullopt;
  mat.softening = SofteningData{v[0], v[1], std::nullopt};
  mat.softening->negative = neg;
  if (r.size() > 4 && !r.text(4).empty()) {
    if (!(v[2] > v[0] / -v[1]))
      failAt(r, 4,
             "the rupture rotation thetaR must exceed the failure jump Mu/|Ks| = " +
                 std::to_string(v[0] / -v[1]));
    mat.softening->thetaR = v[2];
  }
  if (r.size() > 5 && !r.text(5).empty()) {
    if (!(v[3] >= 0 && v[3] < v[0]))
      failAt(r, 5, "the joint's friction moment Mr must lie in [0, Mu)");
    mat.softening->Mr = v[3];
  }
  if (r.size() > 6 && !r.text(6).empty()) {
    if (!(v[4] >= 0)) failAt(r, 6, "the shortest piece Lb must not be negative");
    mat.softening->pieceLength = v[4];
  }
}

void bindRebar(MeshContext& ctx, const Record& r, MaterialSet& mat, LawRecords& seen) {
  if (bindRebarRing(ctx, r, seen)) {
    if (!mat.section) mat.section = RcSectionData{};
    return;
  }
  // REBAr d1 A1 [d2 A2 ...]: the numbers start at field 1 (or 2 after an empty field).
  const std::size_t first = subrecord::firstNumber(r);
  if (r.size() <= first || (r.size() - first) % 2 != 0)
    failAt(r, r.size(), "REBAr takes pairs of depth and area", "write REBAr d1 A1 [d2 A2 ...]");
  if (!mat.section) mat.section = RcSectionData{};
  for (std::size_t i = first; i + 1 < r.size(); i += 2) {
    const double depth = ctx.number(r, i), area = ctx.number(r, i + 1);
    if (!(depth > 0)) failAt(r, i, "a bar layer's depth from the top face must be positive");
    if (!(area > 0)) failAt(r, i + 1, "a bar layer's area must be positive");
    mat.section->bars.push_back({depth, area});
  }
  seen.rebar.push_back(&r);
}

void bindStirrups(MeshContext& ctx, const Record& r, MaterialSet& mat, LawRecords& seen) {
  // STIRrups Asw s [fyw]: the numbers start at field 1 (or 2 after an empty field).
  const std::string syntax = "STIRrups Asw s [fyw]";
  if (seen.stirrups) failAt(r, 0, "STIRrups given twice in one MATErial set");
  const std::size_t first = subrecord::firstNumber(r);
  if (r.size() < first + 2) failAt(r, r.size(), "STIRrups needs Asw and s", "write " + syntax);
  if (r.size() > first + 3) failAt(r, first + 3, "too many values: the record is '" + syntax + "'");
  const double area = ctx.number(r, first), spacing = ctx.number(r, first + 1);
  if (!(area > 0)) failAt(r, first, "the stirrups' area Asw must be positive");
  if (!(spacing > 0)) failAt(r, first + 1, "the stirrups' spacing s must be positive");
  double fyw = 0;  // 0: the bars' fy (finishLawRecords)
  if (r.size() > first + 2 && !r.text(first + 2).empty()) {
    fyw = ctx.number(r, first + 2);
    if (!(fyw > 0)) failAt(r, first + 2, "the stirrups' yield stress fyw must be positive");
  }
  if (!mat.section) mat.section = RcSectionData{};
  mat.section->stirrups = Stirrups{area, spacing, fyw};
  seen.stirrups = &r;
}

void bindInteraction(MeshContext& ctx, const Record& r, const CommandSpec& s, MaterialSet& mat,
                     LawRecords& seen) {
  const std::string syntax = "INTEraction CURVe N1 Mu1 N2 Mu2 ...";
  subrecord::requireText(r, s.name, syntax);
  if (!keywordMatches(r.text(1), "CURVe")) failAt(r, 1, "expected CURVe", "write " + syntax);
  if (r.size() < 6 || r.size() % 2 != 0)
    failAt(r, r.size(), "INTEraction takes two pairs of N and Mu or more", "write " + syntax);
  mat.interaction.clear();
  for (std::size_t i = 2; i + 1 < r.size(); i += 2) {
    const double n = ctx.number(r, i), mu = ctx.number(r, i + 1);
    if (!mat.interaction.empty() && !(n > mat.interaction.back().first))
      failAt(r, i, "the axial forces of the curve must increase");
    if (!(mu > 0)) failAt(r, i + 1, "the curve's moments Mu must be positive");
    mat.interaction.emplace_back(n, mu);
  }
  if (!(mat.interaction.front().first <= 0 && mat.interaction.back().first >= 0))
    failAt(r, 2, "the curve must span N = 0 (its value there scales the laws)");
  seen.interaction = &r;
}

void bindHinges(MeshContext& ctx, const Record& r, const CommandSpec& s, MaterialSet& mat,
                LawRecords& seen) {
  ctx.maxFields(r, 2, "HINGes ENDS / HINGes MIDPoint");
  // The second record would silently win: the set's hinges stand where one record says.
  if (seen.hinges)
    failAt(r, 0,
           "HINGes given twice in one MATErial set (line " + std::to_string(seen.hinges->loc.line) +
               ")",
           "keep one HINGes record: ENDS or MIDPoint");
  if (keywordMatches(r.text(1), "ENDS"))
    mat.hingeSite = HingeSite::Ends;
  else if (keywordMatches(r.text(1), "MIDPoint"))
    mat.hingeSite = HingeSite::Midpoint;
  else
    failAt(r, 1, "unknown option '" + r.text(1) + "' of " + s.name,
           "write HINGes ENDS / HINGes MIDPoint");
  seen.hinges = &r;
}

}  // namespace

bool bindLawRecord(MeshContext& ctx, const Record& r, const CommandSpec& s, MaterialSet& mat,
                   LawRecords& seen) {
  const std::string key = s.key();
  if (key == "hard")
    bindHardening(ctx, r, s, mat, seen);
  else if (key == "soft")
    bindSoftening(ctx, r, s, mat, seen);
  else if (key == "sect")
    bindSectionShape(ctx, r, s, mat, seen);
  else if (key == "reba")
    bindRebar(ctx, r, mat, seen);
  else if (key == "stir")
    bindStirrups(ctx, r, mat, seen);
  else if (key == "inte")
    bindInteraction(ctx, r, s, mat, seen);
  else if (key == "hing")
    bindHinges(ctx, r, s, mat, seen);
  else
    return false;
  return true;
}

void finishLawRecords(const Record& head, const LawRecords& seen, MaterialSet& mat,
                      const Record* elastic, const Record* cross, const Record* resultant) {
  if (seen.hardeningNeg && !seen.hardening)
    failAt(*seen.hardeningNeg, 0,
           "HARDening NEGAtive needs HARDening BILInear (the positive moments')");
  if (seen.softeningNeg && !seen.softening)
    failAt(*seen.softeningNeg, 0,
           "SOFTening NEGAtive needs SOFTening LINEar (the positive moments')");
  if (!seen.rebar.empty() && !seen.section)
    failAt(*seen.rebar.front(), 0, "REBAr without SECTion", "give SECTion RECTangular b h fc fy");
  if (!seen.rings.empty() && !seen.section)
    failAt(*seen.rings.front().record, 0, "REBAr without SECTion",
           "give SECTion CIRCular D fc fy or ANNUlar D t fc fy");
  if (seen.stirrups && !seen.section)
    failAt(*seen.stirrups, 0, "STIRrups without SECTion", "give SECTion RECTangular b h fc fy");
  if (seen.section) {
    const Record& sec = *seen.section;
    const char* why = "SECTion derives the section's stiffnesses and laws";
    for (const Record* other : {elastic, cross, resultant, seen.hardening, seen.hardeningNeg,
                                seen.softening, seen.softeningNeg, seen.interaction})
      if (other) failAt(*other, 0, std::string(why) + ": this record cannot go with it");
    if (seen.hinges && mat.hingeSite != HingeSite::Ends)
      failAt(*seen.hinges, 1, "a SECTion member's hinges open at its ends");
    if (seen.rebar.empty() && seen.rings.empty())
      failAt(sec, 0, "SECTion needs its bars",
             "give REBAr d1 A1 [d2 A2 ...] (depth from the top face, area)");
    if (auto& st = mat.section->stirrups; st && st->fy == 0) st->fy = mat.section->fy;
    std::size_t k = 0;  // the layers in the order of their records
    for (const Record* rb : seen.rebar) {
      const std::size_t first = subrecord::firstNumber(*rb);
      for (std::size_t i = first; i + 1 < rb->size(); i += 2, ++k)
        if (const RebarLayer& l = mat.section->bars[k]; !(l.depth < mat.section->h))
          failAt(*rb, i,
                 "bar layer at depth " + str(l.depth) +
                     " lies outside the section (h = " + str(mat.section->h) + ")");
    }
    placeSectionBars(seen, *mat.section);
    double bars = 0;
    for (const RebarLayer& l : mat.section->bars) bars += l.area;
    const double concrete = SectionShape(*mat.section).area();
    if (!(bars < 0.1 * concrete))
      failAt(sec, 0,
             "the bars' area " + str(bars) + " is not below a tenth of the section's area " +
                 str(concrete),
             "REBAr areas in m^2 (a 20 mm bar: 3.14e-4)");
    try {
      deriveSectionLaws(mat);
      (void)HingedBending(mat);  // the laws the elements will take
    } catch (const std::invalid_argument& e) {
      failAt(sec, 0, std::string("the section's derived laws are not valid: ") + e.what());
    }
    return;
  }
  if (seen.hinges && !mat.softening)
    failAt(*seen.hinges, 0, "HINGes needs a softening law (SOFTening, or SECTion)");
  if (mat.hardening && mat.softening) {
    const double my[2] = {mat.hardening->My, mat.hardening->negative ? mat.hardening->negative->My
                                                                     : mat.hardening->My};
    const double mu[2] = {mat.softening->Mu, mat.softening->negative
                                                 ? mat.softening->negative->first
                                                 : mat.softening->Mu};
    for (int k = 0; k < 2; ++k)
      if (mu[k] < my[k]) {
        const Record* soft = k == 1 && seen.softeningNeg ? seen.softeningNeg : seen.softening;
        std::ostringstream msg;
        msg << "Mu = " << mu[k] << " of SOFTening" << (k == 1 ? " (negative moments)" : "")
            << " is below My = " << my[k] << " of HARDening"
            << (k == 1 ? " (negative moments)" : "");
        failAt(*soft, 2, msg.str(),
               "the hinge forms at Mu, after the hardening up to My: Mu >= My");
      }
  }
  try {
    deriveSectionLaws(mat);
  } catch (const std::invalid_argument& e) {
    failAt(seen.interaction ? *seen.interaction : head, 0, e.what());
  }
}

// ---------------------------------------------------------------------------
// echo

void echoLaws(std::ostream& os, const MaterialSet& m) {
  if (m.hardening) {
    echoLine(os, "Hardening Mc", m.hardening->Mc);
    echoLine(os, "Hardening My", m.hardening->My);
    echoLine(os, "Hardening Kh1", m.hardening->Kh1);
    echoLine(os, "Hardening Kh2", m.hardening->Kh2);
    if (const auto& n = m.hardening->negative) {
      echoLine(os, "Hardening Mc-", n->Mc);
      echoLine(os, "Hardening My-", n->My);
      echoLine(os, "Hardening Kh1-", n->Kh1);
      echoLine(os, "Hardening Kh2-", n->Kh2);
    }
  }
  if (m.softening) {
    echoLine(os, "Softening Mu", m.softening->Mu);
    echoLine(os, "Softening Ks", m.softening->Ks);
    if (const auto& n = m.softening->negative) {
      echoLine(os, "Softening Mu-", n->first);
      echoLine(os, "Softening Ks-", n->second);
    }
    if (m.softening->thetaR && !m.rc) echoLine(os, "Rupture thetaR", *m.softening->thetaR);
    if (m.softening->Mr > 0) echoLine(os, "Joint friction Mr", m.softening->Mr);
    if (m.softening->pieceLength > 0 && !m.rc)
      echoLine(os, "Shortest piece Lb", m.softening->pieceLength);
    if (m.hingeSite == HingeSite::Ends) os << "      Hinges             at the element ends\n";
  }
  if (!m.interaction.empty()) {
    os << "      Interaction curve (N, Mu; the laws scaled by Mu(N)/Mu(0)):\n";
    for (const auto& [n, mu] : m.interaction) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "      %13.4e %13.4e\n", n, mu);
      os << buf;
    }
  }
  if (m.rc) echoSection(os, m);
}

// ---------------------------------------------------------------------------
// specs

void registerLawRecords(CommandRegistry& r) {
  r.add(subSpec(
      "HARDening",
      "HARDening BILInear Mc My Kh1 Kh2: elastoplastic bending, elastic (EI) up to Mc, "
      "hardening modulus Kh1 (moment against plastic curvature) to My, Kh2 beyond. "
      "HARDening NEGAtive Mc My Kh1 Kh2 (after the BILInear record): other values for negative "
      "moments (magnitudes); without it both signs take the same.",
      {text("BILInear/NEGAtive", ""), expr("Mc", "elastic limit moment [kN m]"),
       expr("My", "yield moment [kN m]"), expr("Kh1", "modulus from Mc to My [kN m^2]"),
       expr("Kh2", "modulus beyond My [kN m^2]")}));
  r.add(subSpec(
      "SOFTening",
      "SOFTening LINEar Mu Ks [thetaR [Mr [Lb]]]: softening hinge activated when |M| reaches Mu; "
      "hinge moment Mu + Ks*jump down to zero (Ks < 0). With FINIte kinematics a fully "
      "softened hinge becomes a revolute joint during the run; a joint whose relative "
      "rotation exceeds thetaR (rad) ruptures and the pieces separate (a joint whose node "
      "presses on the ground ruptures when the node leaves it). Mr: the joint's friction "
      "(the broken section's residual moment), a moment Mr opposing its relative rotation, "
      "regularised over the step's relative rotation w: Mr w/sqrt(w^2 + eps^2), eps = Mr "
      "l/EI; dissipated (energy account). Only where the joint is condensed into the "
      "element: a JOINt whose slave node has more than one element (or nodal data) with "
      "Mr > 0 is an error at its record. Lb: the shortest piece the member breaks into: a fully "
      "softened hinge makes no joint at a node within Lb (reference distance) of an intact "
      "joint's node or of a free end, a ruptured joint's included (the failed hinge stays, "
      "carrying no moment), and a joint within Lb of a free end does not rupture past thetaR "
      "(it turns on with its friction; the log says so once); next to a section that carries "
      "no moment the moment grows as V x, "
      "so Lb = Mu/Vu with Vu the shear capacity of the section (e.g. Vc + Vs by ACI 318); 0 "
      "(default): the mesh's node spacing sets the shortest piece; an Lb longer than the set's "
      "longest member (its elements in line) is a located warning (mm?). With FINIte kinematics Lb "
      "is also a localization zone: no midpoint hinge opens in the same member (elements in "
      "line, no joint between) within Lb of an open one (element midpoints, reference "
      "distance), of a joint or of a free or pinned end (from the node; each side of a joint); "
      "the elements there hold their moment at Mu (perfectly plastic) instead (a SECTion with "
      "HINGes MIDPoint and no STIRrups: its depth h). SOFTening "
      "NEGAtive Mu Ks "
      "(after the LINEar record): other values for negative moments; a hinge follows the law of "
      "the sign of its moment at opening.",
      {text("LINEar/NEGAtive", ""), expr("Mu", "ultimate moment [kN m]"),
       expr("Ks", "softening modulus: moment per radian of jump [kN m/rad], negative"),
       expr("thetaR", "rupture rotation of the joint [rad] (optional)"),
       expr("Mr", "friction moment of the joint [kN m] (optional, 0)"),
       expr("Lb", "shortest piece: no joint within Lb of a joint or free end [m] (optional, 0)")}));
  r.add(subSpec(
      "SECTion",
      "SECTion RECTangular b h fc fy [Es [fu eu]]: a rectangular reinforced concrete section "
      "(with REBAr for its bars), instead of ELAStic/CROSs/RESUltant/HARDening/SOFTening. "
      "Other shapes, the same rules: SECTion TEE bw h beff hf fc fy [Es [fu eu]] (a beam with "
      "its slab: web width bw, total depth h, effective flange width beff >= bw (EC2 5.3.2.1) "
      "and thickness hf < h at the top face, so a positive moment compresses the flange; the "
      "slab's bars among the REBAr layers); SECTion CIRCular D fc fy [Es [fu eu]] (solid "
      "circle); SECTion ANNUlar D t fc fy [Es [fu eu]] (hollow circle, wall t < D/2: "
      "chimneys, towers, piers); their bars as layers or REBAr RING n A c. The concrete's "
      "stress is integrated over the shape exactly (rectangles: Gauss points on the pieces "
      "between the plane's kinks; circles: the chord width 2 r sin(phi) at z = zc - r "
      "cos(phi), closed form), moments about the concrete's gross centroid (the member's "
      "axis: mid-depth of rectangles and circles; a T-section's lies in or near the "
      "flange), A and I the gross shape's (mass, rotary inertia). "
      "Materials of Eurocode 2: concrete parabola-rectangle (eps_c2 = 0.002, eps_cu2 = 0.0035, "
      "C50/60 at most), fc used as given (give the strength the analysis should see, a mean "
      "strength for a collapse), Ec = 2 fc/eps_c2 (the parabola's initial slope: one law for "
      "stiffness and strength), fct = fc/10, no tension in the cracked states; bars elastic-"
      "perfectly plastic, fracturing at eu. Derived, echoed in the log: EA, EI of the "
      "transformed uncracked section (the concrete's shape, bars (Es/Ec - 1) A: the elastic "
      "branch of the law is the uncracked member, cracking is its first hardening branch), GA "
      "= Ec/2.4 times the shear area (5/6 b h, the web's 5/6 bw h for TEE, Cowper's factor "
      "of the solid or hollow circle times A); at every axial force N (tension positive) and for "
      "each sign of the moment "
      "(positive compresses the top face: the face on the element's left from its first node "
      "to its second): Mc (the tension face at fct, transformed section), My and kappa_y "
      "(first yield: the most strained bar at fy/Es or the compressed face at eps_c2), Mu and "
      "kappa_u (the compressed face at eps_cu2, or eps_c2 at 3h/7 when the whole section is "
      "compressed, or a bar at eu; EC2 6.1), the hardening moduli Kh1 = (My - Mc)/(kappa_y - "
      "My/EI), Kh2 = (Mu - My)/(plastic curvature from My to Mu): the law passes through the "
      "section's moment-curvature points. Tabulated on [-Nc, Nt] "
      "(monotone cubic in N). Hinges open at the element ends (the end moments of the "
      "element's equilibrium) as joints with the softening law: plastic rotation capacity "
      "theta_pl = (kappa_uc - kappa_y) Lpl (1 - 0.5 Lpl/L_V) (EN 1998-3 A.3.2.2 (A.9), mean: "
      "gamma_el = 1), Lpl = L_V/30 + 0.2 h + 0.11 dbL fy/sqrt(fc) (A.10, fy and fc in MPa read "
      "from fc's magnitude; the term left out when it is not recognised), at most L_V; L_V = "
      "M/V, the shear span, taken where the hinge opens from the element's end moments (L "
      "|Ma|/|Ma - Mb|: a cantilever's length, L/2 in double curvature), within [h, 10 h], "
      "logged on the hinge's line; dbL the tension bars' diameter estimated from the farthest "
      "layer's area (its corner bars and bars at most 0.15 m apart across the width; a ring's "
      "one bar); kappa_uc the curvature at which the compressed face reaches the confined "
      "core's eps_cu,c with the concrete at fcc (STIRrups; eps_cu2 = 0.0035 and fc without "
      "them) or a bar eu (Mu stays the unconfined section's), the moment falling linearly from "
      "Mu and 20 % lower at theta_pl (Panagiotakos and Fardis' ultimate: a 20 % drop): "
      "failure jump xiF = 5 theta_pl, Ks = -Mu/xiF, taken at the axial force of the "
      "hinge's opening (echoed at N = 0 and the reference L_V = 4 h, which midpoint hinges "
      "take); the joint then turns freely (the bars hold the pieces) and "
      "ruptures at thetaR = xiF(N = 0, L_V = 10 h) + acos(1/(1 + eu)) (a tie pinned there turned so far has "
      "its bars at eu). Echoed beside them: EN 1998-3 (A.1)'s mean chord rotation at ultimate "
      "(the 20 % drop, cyclic tests) without its shear-span factor, theta_um/(L_V/h)^0.35 = "
      "0.016 0.3^nu [max(0.01, w')/max(0.01, w) fc]^0.225 25^(alpha rho_sx fyw/fc) at N = 0 "
      "(w, w' = As fy/(b d fc) of the bars in the tension and compression halves, fc in MPa "
      "read from its magnitude: 5-150 MPa, 5e3-1.5e5 kN/m^2, 5e6-1.5e8 Pa), for comparison "
      "with the member's chord rotation (docs/design/rc-rotation-capacity.md). Axial force: elastic with the uncracked EA in compression and the "
      "cracked tie's Es As in tension (the member's strain is then its bars'), bounded by the "
      "bars in tension, Nt = As fy hardening to Ntu = As fu at the strain eu, where the bars "
      "fracture and the member separates from one of its ends (one log line each), and by the "
      "squash load Nc = fc Ac + As min(fy, Es eps_c2) in compression (Ac the concrete's area). Mc, "
      "My, Mu follow N "
      "(moment-axial "
      "interaction): the hardening and softening variables are kept when N changes. "
      "Defaults: Es = 200e6 (kN/m^2: 200 GPa; give it in another unit system), fu = 1.08 fy, "
      "eu = 0.05 (EC2 Annex C class B). Units of the derived values in the decks' system "
      "(kN, m, s, t): EA, GA and Nc, Nt, Ntu kN; EI kN m^2; Mc, My, Mu kN m; curvatures "
      "kappa 1/m; Kh1, Kh2 kN m^2 (moment per plastic curvature); Ks kN m/rad; theta_pl, "
      "xiF, thetaR rad. The shear capacity Vu(N) (EC2 6.2.2 and 6.2.3, see STIRrups) is "
      "empirical in MPa and mm: it reads fc in kN/m^2 and lengths in m (1 kN/m^2 = 1e-3 MPa, "
      "1 m = 1000 mm), and a fc outside 1e3-2.5e5 (1-250 MPa) is refused as surely in another "
      "unit. A member whose shear reaches Vu(N) at a state of the run fails in shear there, "
      "located like a hinge event, and separates from one of its ends (one log line: element, "
      "time, V, Vu, N). Values accepted but surely in another unit are located warnings naming "
      "the likely unit and the value in kN/m^2 or m (fc = 30 ...: MPa? 30 MPa is 30e3 "
      "kN/m^2), and a run that then fails names them in its advice: fc outside 5e3-1.5e5, fy "
      "and a given fu outside 1e5-2.5e6 (100-2500 MPa), a given Es outside 1e8-3e8, a size "
      "above 30 m, a REBAr layer above 0.05 m^2 (a RING's bar above 5e-3), and a depth h "
      "longer than the set's longest member (its elements in line), checked once the mesh "
      "is built.",
      {text("RECTangular/TEE/CIRCular/ANNUlar", "the shape"),
       expr("b", "width [m] (TEE: bw h beff hf; CIRCular: D; ANNUlar: D t)"),
       expr("h", "depth [m]"), expr("fc", "concrete compressive strength [kN/m^2]"),
       expr("fy", "bar yield stress [kN/m^2]"), expr("Es", "bar modulus [kN/m^2]", "200e6"),
       expr("fu", "bar ultimate stress [kN/m^2]", "1.08 fy"),
       expr("eu", "bar fracture strain [-]", "0.05")}));
  r.add(subSpec(
      "REBAr",
      "REBAr d1 A1 [d2 A2 ...]: the bars of a SECTion as layers, each its depth from the top "
      "face (the face a positive moment compresses) and its area; more REBAr records add "
      "layers. REBAr RING n A c (CIRCular, ANNUlar): n bars of area A each, evenly on a "
      "circle whose cover c is the distance from the outer face to the bars' centres (inside "
      "the concrete: c < D/2, for ANNUlar c < t), the first bar on the top face's side; they "
      "become layers, one per depth (the bars at +-theta share it), echoed in the log.",
      {expr("d1", "depth of the layer from the top face [m]"),
       expr("A1", "area of the layer's bars [m^2]")}));
  r.add(subSpec(
      "STIRrups",
      "STIRrups Asw s [fyw]: the links of a SECTion: the area Asw of their legs across the "
      "section (two legs of 8 mm: 1.0e-4 m^2), their spacing s along the member and yield "
      "stress fyw (default: the bars' fy). The member's shear capacity at its axial force N "
      "(tension positive), EC2 with strengths as given (no partial factors): the concrete's "
      "VRd,c = [max(0.18 k (100 rho_l fc)^(1/3), vmin) + 0.15 sigma_cp] bw d (6.2.2, MPa and "
      "mm inside: k = 1 + sqrt(200/d) <= 2, rho_l = Asl/(bw d) <= 0.02 with Asl the bars in "
      "the half away from the compressed face, vmin = 0.035 k^1.5 fc^0.5, sigma_cp = -N/Ac "
      "<= 0.2 fc, a tension lowering it down to 0; bounded by 0.5 nu fc bw d, nu = 0.6 (1 - "
      "fc/250)); the stirrups' VRd,s = Asw/s z fyw cot theta (6.8, z = 0.9 d, d the depth of "
      "the farthest bars) bounded by the struts' VRd,max = alpha_cw bw z nu fc / (cot theta + "
      "tan theta) (6.9; alpha_cw = 1 + sigma_cp/fc up to 0.25 fc, 1.25 to 0.5 fc, 2.5 (1 - "
      "sigma_cp/fc) beyond, 1 in tension), at the strut angle 1 <= cot theta <= 2.5 that "
      "carries the most; Vu = max(VRd,c, VRd,s): EC2 counts the stirrups alone where they "
      "are needed (the concrete's share is in the flatter strut), and a member does not fail "
      "before its concrete alone would. Of the two signs of the moment the smaller. Without "
      "STIRrups Vu = VRd,c. A member whose shear reaches Vu(N) fails in shear and separates "
      "from one of its ends. From Vu the shortest piece the "
      "member breaks into, Lb = the larger of Mu(0)/Vu(0) of the two signs: next to a section "
      "that carries no moment (a ruptured joint, a free end) the moment grows as V x, so no "
      "hinge can reach Mu nearer than Mu/Vu. A joint within Lb of a free end does not "
      "rupture (it turns on with its friction), and a failed midpoint hinge within Lb of an "
      "intact joint or a free end makes no joint, as SOFTening's Lb. The links also confine the core "
      "and so set the hinge's rotation capacity (EN 1998-3 A.3.2.2): core b0 = b - 2c, h0 = "
      "the distance between the outermost bar layers (c the least layer depth: the hoops' "
      "centre lines taken at the bars'), effectiveness alpha = (1 - s/(2 b0))(1 - s/(2 h0))"
      "(1 - sum bi^2/(6 b0 h0)) with a perimeter hoop restraining the four corner bars (bi = "
      "b0, b0, h0, h0: 1/3 for a square core; cross-ties not counted), rho_sx = Asw/(b s), "
      "fcc = fc (1 + 3.7 (alpha rho_sx fyw/fc)^0.86) (A.11), eps_cu,c = 0.004 + 0.5 alpha "
      "rho_sx fyw/fcc (A.12), at least eps_cu2 = 0.0035: the ultimate curvature of the "
      "hinge's plastic rotation (SECTion), with the concrete at fcc and eps_c2,c = eps_c2 "
      "(fcc/fc)^2 (EC2 3.1.9). Echoed: VRd,c, VRd,s, cot theta and Vu of either sign at "
      "N = 0, Vu(N) in the interaction table, Lb, b0, h0, alpha, rho_sx, fcc, eps_cu,c. "
      "Located warnings, as SECTion's unit checks: Asw/(b s) above 0.1 (Asw in cm^2 or "
      "mm^2?), a given fyw outside 1e5-2.5e6, s above the depth h (a 45-degree crack may "
      "cross no link; EC2 9.2.2(6) allows 0.75 d in beams, 9.5.3 the smaller of 20 bar "
      "diameters, the smaller side and 0.4 m in columns: between those and h a detailing "
      "choice, not warned) or above the set's longest member. Lb longer than the member is "
      "not warned (a shear-critical member).",
      {expr("Asw", "area of the stirrups' legs at one section [m^2]"),
       expr("s", "spacing along the member [m]"),
       expr("fyw", "stirrups' yield stress [kN/m^2]", "fy")}));
  r.add(subSpec(
      "INTEraction",
      "INTEraction CURVe N1 Mu1 N2 Mu2 ...: hand-given laws (HARDening, SOFTening) that follow "
      "the axial force: every moment and modulus of either sign is multiplied by Mu(N)/Mu(0), "
      "the curve interpolated by a monotone cubic (constant beyond its ends); the N must "
      "increase and span 0 (tension positive).",
      {text("CURVe", ""), expr("N1", "axial force [kN]"), expr("Mu1", "ultimate moment [kN m]")}));
  r.add(subSpec(
      "HINGes",
      "HINGes ENDS: the softening hinges open at the element ends, where the end moment of the "
      "element's equilibrium first reaches Mu, as joints carrying the softening law (SECTion "
      "members always do); a coarse mesh then sees the support moments. HINGes MIDPoint "
      "(default for hand-given laws): at the one-point element's midpoint when its moment "
      "reaches Mu (the paper's element).",
      {text("ENDS/MIDPoint", "", "MIDPoint")}));
}

}  // namespace c2d
