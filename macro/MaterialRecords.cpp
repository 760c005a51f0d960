#include "macro/MaterialRecords.h"

#include <cmath>
#include <numbers>
#include <string>

#include "macro/MeshCommands.h"

namespace c2d {

using namespace meshspec;

namespace {

CommandSpec subSpec(std::string name, std::string doc, std::vector<FieldSpec> fields) {
  CommandSpec s;
  s.name = std::move(name);
  s.doc = std::move(doc);
  s.fields = std::move(fields);
  s.section = CommandSection::SubRecord;
  return s;
}

}  // namespace

void registerMaterialSubRecords(CommandRegistry& r) {
  r.add(subSpec("FRAMe", "Element type: two-node plane frame (first record of MATErial).", {}));
  r.add(subSpec("ELAStic", "ELAStic ISOTropic E nu: Young's modulus and Poisson ratio.",
                {text("ISOTropic", "the only kind for frames"), expr("E", "modulus"),
                 expr("nu", "Poisson ratio", "0")}));
  r.add(subSpec("CROSs",
                "CROSs SECTion A I [Iyy Ixy J kappa kappa2] (FEAPpv's record): a plane frame "
                "uses A, I and the shear factor kappa (0: 5/6).",
                {text("SECTion", "any word"), expr("A", "area"), expr("I", "second moment of area"),
                 expr("Iyy", "ignored in 2D", "0"), expr("Ixy", "ignored in 2D", "0"),
                 expr("J", "ignored in 2D", "0"), expr("kappa", "shear factor", "5/6"),
                 expr("kappa2", "ignored in 2D", "0")}));
  r.add(subSpec("SHEAr", "SHEAr ON: Timoshenko (default); SHEAr OFF: Euler-Bernoulli.",
                {text("ON/OFF", "", "ON")}));
  r.add(subSpec("SMALl", "Geometrically linear kinematics (default).", {}));
  r.add(subSpec("FINIte", "Geometrically exact (Reissner) kinematics.", {}));
  r.add(subSpec("DENSity", "DENSity,,rho: mass per unit volume.",
                {text("", "empty"), expr("rho", "density")}));
  r.add(subSpec("MASS", "MASS LUMPed or MASS CONSistent (default).",
                {text("LUMPed/CONSistent", "", "CONSistent")}));
  r.add(subSpec(
      "RESUltant",
      "RESUltant STIFfness EA GA EI: stress-resultant stiffnesses instead of ELAStic + "
      "CROSs (GA includes the shear factor).",
      {text("STIFfness", ""), expr("EA", "axial"), expr("GA", "shear"), expr("EI", "bending")}));
  r.add(subSpec("HARDening",
                "HARDening BILInear Mc My Kh1 Kh2: elastoplastic bending, elastic up to Mc, "
                "modulus Kh1 to My, Kh2 beyond.",
                {text("BILInear", ""), expr("Mc", "moment"), expr("My", "moment"),
                 expr("Kh1", "modulus"), expr("Kh2", "modulus")}));
  r.add(subSpec(
      "SOFTening",
      "SOFTening LINEar Mu Ks [thetaR [Mr]]: softening hinge activated when |M| reaches Mu; "
      "hinge moment Mu + Ks*jump down to zero (Ks < 0). With FINIte kinematics a fully "
      "softened hinge becomes a revolute joint during the run; a joint whose relative "
      "rotation exceeds thetaR (rad) ruptures and the pieces separate (a joint whose node "
      "presses on the ground ruptures when the node leaves it). Mr: the joint's friction "
      "(the broken section's residual moment), a moment Mr opposing its relative rotation, "
      "regularised over the step's relative rotation w: Mr w/sqrt(w^2 + eps^2), eps = Mr "
      "l/EI; dissipated (energy account). Only where the joint is condensed into the "
      "element: a JOINt whose slave node has more than one element (or nodal data) with "
      "Mr > 0 is an error at its record.",
      {text("LINEar", ""), expr("Mu", "ultimate moment"), expr("Ks", "softening modulus"),
       expr("thetaR", "rupture rotation of the joint (optional)"),
       expr("Mr", "friction moment of the joint (optional, 0)")}));
  r.add(
      subSpec("DAMPing",
              "DAMPing RAYLeigh 0 a1 (FEAPpv's record) or DAMPing RATIo zeta f: structural damping "
              "of the members in dynamics, a Kelvin-Voigt dashpot in parallel with the section, "
              "stiffness proportional: resultants a1 (EA, GA, EI) times the section's strain rates "
              "over the step, in bending the elastic curvature's (not a hinge's rotation). a1 in "
              "seconds (time units); RATIo gives the damping ratio zeta (e.g. 0.05) at the "
              "frequency f in Hz, a1 = zeta/(pi f); a mode of frequency f' then has the ratio "
              "zeta f'/f. a0 (mass proportional) must be 0: it would brake rigid motion, a free "
              "fall among them. The dashpot's work is dissipated (energy account); none in "
              "statics.",
              {text("RAYLeigh/RATIo", ""), expr("a0/zeta", "0 / damping ratio"),
               expr("a1/f", "coefficient (s) / frequency (Hz)")}));
}

double readDamping(const MeshContext& ctx, const Record& r) {
  const std::string syntax = "DAMPing RAYLeigh 0 a1 or DAMPing RATIo zeta f";
  const std::string kind = r.text(1);
  const bool rayleigh = keywordMatches(kind, "RAYLeigh"), ratio = keywordMatches(kind, "RATIo");
  if (!rayleigh && !ratio)
    failAt(r, 1,
           kind.empty() ? "DAMPing needs its kind, RAYLeigh or RATIo"
                        : "unknown option '" + kind + "' of DAMPing",
           "write " + syntax);
  ctx.maxFields(r, 4, syntax);
  if (r.size() < 4) failAt(r, r.size(), "DAMPing needs two values", "write " + syntax);
  const double v1 = ctx.number(r, 2), v2 = ctx.number(r, 3);
  if (rayleigh) {
    if (v1 != 0)
      failAt(r, 2, "mass-proportional damping (a0) would brake the members' rigid motion",
             "give a0 = 0: the members are damped through their strain rates (a1)");
    if (!(v2 >= 0)) failAt(r, 3, "the coefficient a1 must not be negative");
    return v2;
  }
  if (!(v1 >= 0 && v1 < 1)) failAt(r, 2, "the damping ratio zeta must lie in [0, 1)");
  if (!(v2 > 0)) failAt(r, 3, "the frequency f (Hz) must be positive");
  return v1 / (std::numbers::pi * v2);
}

}  // namespace c2d
