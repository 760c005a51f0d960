#include "macro/mesh/Units.h"

#include <vector>

namespace c2d::units {

namespace {

// Units of the decks' system.
constexpr const char* kNone = "-";  // counts, numbers of nodes, codes, factors, ratios
constexpr const char* kLength = "m";
constexpr const char* kForce = "kN";
constexpr const char* kMoment = "kN m";
constexpr const char* kStress = "kN/m^2";
constexpr const char* kTime = "s";
constexpr const char* kRotation = "rad";

struct Field {
  CommandSection section;
  const char* key;
  const char* field;
  const char* unit;
};

// The command records' fields (FieldSpec names). Text fields have "".
const std::vector<Field>& fields() {
  using S = CommandSection;
  static const std::vector<Field> table = {
      // Mesh commands.
      {S::Mesh, "mate", "m", kNone},
      {S::Mesh, "mate", "label", ""},
      {S::Mesh, "ebou", "mode", ""},
      {S::Mesh, "efor", "mode", ""},
      {S::Mesh, "edis", "mode", ""},
      {S::Mesh, "cbou", "mode", ""},
      {S::Mesh, "cfor", "mode", ""},
      {S::Mesh, "cdis", "mode", ""},
      {S::Mesh, "grav", "", ""},
      {S::Mesh, "grav", "gx", "m/s^2"},
      {S::Mesh, "grav", "gy", "m/s^2"},
      {S::Mesh, "infi", "", ""},
      {S::Mesh, "infi", "t", kLength},
      {S::Mesh, "infi", "fm", kStress},
      {S::Mesh, "infi", "Em", kStress},
      {S::Mesh, "infi", "rho", "t/m^3"},
      {S::Mesh, "infi", "open", kNone},
      {S::Mesh, "site", "", ""},
      {S::Mesh, "site", "xmin", kLength},
      {S::Mesh, "site", "xmax", kLength},
      {S::Mesh, "site", "dir", ""},
      {S::Mesh, "incl", "file", ""},
      // Material sub-records.
      {S::SubRecord, "elas", "ISOTropic", ""},
      {S::SubRecord, "elas", "E", kStress},
      {S::SubRecord, "elas", "nu", kNone},
      {S::SubRecord, "cros", "SECTion", ""},
      {S::SubRecord, "cros", "A", "m^2"},
      {S::SubRecord, "cros", "I", "m^4"},
      {S::SubRecord, "cros", "Iyy", "m^4"},
      {S::SubRecord, "cros", "Ixy", "m^4"},
      {S::SubRecord, "cros", "J", "m^4"},
      {S::SubRecord, "cros", "kappa", kNone},
      {S::SubRecord, "cros", "kappa2", kNone},
      {S::SubRecord, "shea", "ON/OFF", ""},
      {S::SubRecord, "dens", "", ""},
      {S::SubRecord, "dens", "rho", "t/m^3"},
      {S::SubRecord, "radi", "", ""},
      {S::SubRecord, "radi", "r", "m"},
      {S::SubRecord, "mass", "LUMPed/CONSistent", ""},
      {S::SubRecord, "resu", "STIFfness", ""},
      {S::SubRecord, "resu", "EA", kForce},
      {S::SubRecord, "resu", "GA", kForce},
      {S::SubRecord, "resu", "EI", "kN m^2"},
      {S::SubRecord, "damp", "RAYLeigh/RATIo", ""},
      {S::SubRecord, "damp", "a0/zeta", "0 / none (a ratio)"},
      {S::SubRecord, "damp", "a1/f", "s / Hz"},
      {S::SubRecord, "hard", "BILInear/NEGAtive", ""},
      {S::SubRecord, "hard", "Mc", kMoment},
      {S::SubRecord, "hard", "My", kMoment},
      {S::SubRecord, "hard", "Kh1", "kN m^2"},
      {S::SubRecord, "hard", "Kh2", "kN m^2"},
      {S::SubRecord, "soft", "LINEar/NEGAtive", ""},
      {S::SubRecord, "soft", "Mu", kMoment},
      {S::SubRecord, "soft", "Ks", "kN m/rad"},
      {S::SubRecord, "soft", "thetaR", kRotation},
      {S::SubRecord, "soft", "Mr", kMoment},
      {S::SubRecord, "soft", "Lb", kLength},
      {S::SubRecord, "sect", "RECTangular/TEE/CIRCular/ANNUlar", ""},
      {S::SubRecord, "sect", "b", kLength},
      {S::SubRecord, "sect", "h", kLength},
      {S::SubRecord, "sect", "fc", kStress},
      {S::SubRecord, "sect", "fy", kStress},
      {S::SubRecord, "sect", "Es", kStress},
      {S::SubRecord, "sect", "fu", kStress},
      {S::SubRecord, "sect", "eu", kNone},
      {S::SubRecord, "reba", "d1", kLength},
      {S::SubRecord, "reba", "A1", "m^2"},
      {S::SubRecord, "stir", "Asw", "m^2"},
      {S::SubRecord, "stir", "s", kLength},
      {S::SubRecord, "stir", "fyw", kStress},
      {S::SubRecord, "inte", "CURVe", ""},
      {S::SubRecord, "inte", "N1", kForce},
      {S::SubRecord, "inte", "Mu1", kMoment},
      {S::SubRecord, "hing", "ENDS/MIDPoint", ""},
      // Solution commands.
      {S::Solution, "loop", "label", ""},
      {S::Solution, "loop", "n", kNone},
      {S::Solution, "next", "label", ""},
      {S::Solution, "tang", "option", ""},
      {S::Solution, "tang", "n", kNone},
      {S::Solution, "utan", "option", ""},
      {S::Solution, "utan", "n", kNone},
      {S::Solution, "form", "option", ""},
      {S::Solution, "tol", "option", ""},
      {S::Solution, "tol", "etol", "- (ENER: kN m)"},
      {S::Solution, "tol", "rtol", kNone},
      {S::Solution, "dt", "-", ""},
      {S::Solution, "dt", "dt", kTime},
      {S::Solution, "time", "option", ""},
      {S::Solution, "time", "tmax", kTime},
      {S::Solution, "time", "ratio", kNone},
      {S::Solution, "time", "hold", kTime},
      {S::Solution, "back", "-", ""},
      {S::Solution, "back", "dt", kTime},
      {S::Solution, "prop", "-", ""},
      {S::Solution, "prop", "n", kNone},
      {S::Solution, "arcl", "option", ""},
      {S::Solution, "arcl", "kfl", kNone},
      {S::Solution, "arcl", "lfl", kNone},
      {S::Solution, "auto", "mode", ""},
      {S::Solution, "auto", "dtmin", kTime},
      {S::Solution, "auto", "pred", kNone},
      {S::Solution, "dyna", "scheme", ""},
      {S::Solution, "dyna", "p1", kNone},
      {S::Solution, "dyna", "p2", kNone},
      {S::Solution, "tran", "scheme", ""},
      {S::Solution, "tran", "p1", kNone},
      {S::Solution, "tran", "p2", kNone},
      {S::Solution, "disp", "option", ""},
      {S::Solution, "disp", "n1", kNone},
      {S::Solution, "disp", "n2", kNone},
      {S::Solution, "disp", "inc", kNone},
      {S::Solution, "velo", "option", ""},
      {S::Solution, "velo", "n1", kNone},
      {S::Solution, "velo", "n2", kNone},
      {S::Solution, "velo", "inc", kNone},
      {S::Solution, "acce", "option", ""},
      {S::Solution, "acce", "n1", kNone},
      {S::Solution, "acce", "n2", kNone},
      {S::Solution, "acce", "inc", kNone},
      {S::Solution, "reac", "option", ""},
      {S::Solution, "reac", "n1", kNone},
      {S::Solution, "reac", "n2", kNone},
      {S::Solution, "reac", "inc", kNone},
      {S::Solution, "stre", "option", ""},
      {S::Solution, "stre", "n1", kNone},
      {S::Solution, "stre", "n2", kNone},
      {S::Solution, "stre", "inc", kNone},
      {S::Solution, "tplo", "-", ""},
      {S::Solution, "tplo", "inc", kNone},
      {S::Solution, "plot", "kind", ""},
      {S::Solution, "plot", "p1", kNone},
      {S::Solution, "plot", "p2", kNone},
      {S::Solution, "pvie", "option", ""},
      {S::Solution, "pvie", "inc", kNone},
      {S::Solution, "mesh", "file", ""},
      {S::Solution, "hing", "option", ""},
      {S::Solution, "remo", "option", ""},
      {S::Solution, "remo", "n1", kNone},
      {S::Solution, "remo", "n2", kNone},
      {S::Solution, "remo", "inc", kNone},
      {S::Solution, "remo", "td", kTime},
      {S::Solution, "save", "name", ""},
      {S::Solution, "rest", "name", ""},
      {S::Solution, "para", "name", ""},
      {S::Solution, "para", "value", "the parameter's"},
  };
  return table;
}

struct Data {
  CommandSection section;
  const char* key;
  const char* units;
};

// The data records' fields.
const std::vector<Data>& data() {
  using S = CommandSection;
  static const std::vector<Data> table = {
      {S::Mesh, "coor", "node, ng [-]; x, y [m]"},
      {S::Mesh, "mate", "those of the material sub-records"},
      {S::Mesh, "elem", "elem, ng, mat, n1, n2 [-]"},
      {S::Mesh, "boun", "node, ng, codes c1 c2 c3 [-]"},
      {S::Mesh, "forc", "node, ng [-]; f1, f2 [kN]; f3 [kN m]"},
      {S::Mesh, "disp", "node, ng [-]; d1, d2 [m]; d3 [rad]"},
      {S::Mesh, "fpro", "node, ng, table numbers p1 p2 p3 [-]"},
      {S::Mesh, "ebou", "idir [-]; x [m]; codes [-]"},
      {S::Mesh, "efor", "idir [-]; x [m]; f1, f2 [kN]; f3 [kN m]"},
      {S::Mesh, "edis", "idir [-]; x [m]; d1, d2 [m]; d3 [rad]"},
      {S::Mesh, "cbou", "x, y [m]; codes [-]"},
      {S::Mesh, "cfor", "x, y [m]; f1, f2 [kN]; f3 [kN m]"},
      {S::Mesh, "cdis", "x, y [m]; d1, d2 [m]; d3 [rad]"},
      {S::Mesh, "bloc", "n, node1, elem1, mat, i [-]; x, y [m]"},
      {S::Mesh, "join", "master, slave [-]"},
      {S::Mesh, "cont",
       "GROUnd: y0 [m], k [kN/m], alpha, mu, e [-]; MEMBers: k [kN/m], alpha [-], r [m], mu, e [-]"},
      {S::Mesh, "shif", "x0, y0 [m]"},
      {S::Mesh, "pola", "n1, n2, inc [-]; dx, dy [m]; r [m], theta [degrees] of the nodes"},
      {S::Mesh, "qloa", "n1, n2, inc [-]; qx, qy [kN/m]"},
      {S::Mesh, "mass", "node, ng [-]; m1, m2 [t]; m3 [t m^2]"},
      {S::Mesh, "site", "x1, x2, h [m]; mass [t]; FLYRock mass [t]; RISK p, confidence [-]"},
      {S::Mesh, "blas", "t [s]; n1, n2, inc [-]; td [s]"},
      {S::Mesh, "infi", "n1 n2 n3 n4, ng, dn [-]"},
      {S::Mesh, "weak", "factor, n1, n2, inc [-]"},
      {S::Mesh, "rigi", "e [-]; offset1, offset2 [m]"},
      {S::Mesh, "para", "the expression's (a parameter has the unit of the fields it is used in)"},
      {S::Mesh, "feap", "numnp numel nummat ndm ndf nen [-]"},
      {S::Mesh, "swee", "the values' (those of the fields the parameter is used in)"},
      {S::Solution, "prop",
       "type, k [-]; tmin, tmax, t [s]; a1 .. a5, p [-] (a4 per s: tau in s)"},
      {S::Solution, "arcl", "ndamp, dlambda0, node, dof [-]; increment [m or rad]"},
      {S::Solution, "tplo", "kind, n, d [-] (the columns: those of the quantities: m, rad, kN, kN m, kJ)"},
      {S::Solution, "plot", "column names"},
      {S::Solution, "mesh", "the mesh commands'"},
      {S::Solution, "para", "the expression's"},
  };
  return table;
}

bool sameKey(std::string_view a, std::string_view b) { return a == b; }

}  // namespace

std::optional<std::string> ofField(CommandSection section, std::string_view key,
                                   std::string_view field) {
  for (const Field& f : fields())
    if (f.section == section && sameKey(f.key, key) && field == f.field) return std::string(f.unit);
  return std::nullopt;
}

std::string ofDataRecords(CommandSection section, std::string_view key) {
  for (const Data& d : data())
    if (d.section == section && sameKey(d.key, key)) return d.units;
  return {};
}

std::string systemHelp() {
  return "Units. The program has no units of its own: every number of a deck is in one consistent "
         "system, and the results are in it. The decks here and --help use kN, m, s, t: lengths m, "
         "forces kN, time s, mass t (1000 kg; kN = t m/s^2), so moments kN m, stresses and moduli "
         "kN/m^2 (1 MPa = 1000 kN/m^2), EI kN m^2, EA and GA kN, densities t/m^3 (concrete 2.5), "
         "line loads kN/m, penalty stiffnesses kN/m, rotations rad, energies kN m = kJ, gravity "
         "GRAVity,,0,-9.81. Another consistent system works the same way once every number is "
         "given in it: N, mm, s, t (stresses N/mm^2 = MPa, densities t/mm^3: 2.5e-9 for concrete, "
         "gravity -9810 mm/s^2, moments N mm) or N, m, s, kg (Pa, kg/m^3, -9.81). A hard-wired "
         "default belongs to the decks' system: SECTion's Es = 200e6 (200 GPa in kN/m^2), to be "
         "given in another system; SECTion's other rules (Ec = 2 fc/eps_c2, fct = fc/10, fu = 1.08 "
         "fy, eu = 0.05) hold in any. The debris report's m and t are those of the decks' system "
         "(read them in the deck's).";
}

}  // namespace c2d::units
