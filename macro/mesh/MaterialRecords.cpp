#include "macro/mesh/MaterialRecords.h"

#include <cmath>
#include <numbers>
#include <string>

#include "macro/mesh/MeshCommands.h"
#include "macro/mesh/SectionRecords.h"

namespace c2d {

using namespace meshspec;

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
  r.add(subSpec("RADIus",
                "RADIus,,r: the members' contact radius (m) with each other and the one the "
                "ground's burial check uses, in place of the section's half depth sqrt(3 I/A): "
                "a wall in the plane whose own floors' arms lie within its half length.",
                {text("", "empty"), expr("r", "contact radius (m)")}));
  r.add(subSpec("MASS", "MASS LUMPed or MASS CONSistent (default).",
                {text("LUMPed/CONSistent", "", "CONSistent")}));
  r.add(subSpec(
      "RESUltant",
      "RESUltant STIFfness EA GA EI: stress-resultant stiffnesses instead of ELAStic + "
      "CROSs (GA includes the shear factor).",
      {text("STIFfness", ""), expr("EA", "axial"), expr("GA", "shear"), expr("EI", "bending")}));
  registerLawRecords(r);
  r.add(
      subSpec("DAMPing",
              "DAMPing RAYLeigh 0 a1 (FEAPpv's record) or DAMPing RATIo zeta f: structural damping "
              "of the members in dynamics, a Kelvin-Voigt dashpot in parallel with the section, "
              "stiffness proportional: resultants a1 (EA, GA, EI) times the section's strain rates "
              "over the step, in bending the elastic curvature's (not a hinge's rotation), axially "
              "for SECTion members the elastic strain's (not the bars' yielding or the "
              "crushing); with SECTion or INTEraction the moment follows N as without. a1 in "
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
