// The solution commands that print and write results (DISP, VELO, ACCE, REAC,
// STRE, TPLOt, PLOT, PVIEw: their list is outputCommands() of
// SolutionCommandKit.h); the columns PLOT,CURVe reads are macro/run/PlotColumns.h's.
#include <algorithm>
#include <array>
#include <cstdio>

#include "macro/run/PlotColumns.h"
#include "macro/run/ProblemRun.h"
#include "macro/solution/SolutionCommandKit.h"

namespace c2d {

namespace {

using namespace batchspec;

[[noreturn]] void failData(const Record& rec, std::size_t field, const std::string& what,
                           const std::string& hint = {}) {
  throw DeckError(rec.fieldLoc(field), what, rec.excerpt(rec.fieldLoc(field)), hint);
}

// Number i of the command, or def when the field is absent or empty.
double value(const Macro& m, std::size_t i, const Parameters& p, double def) {
  return m.has(i) && !m.record.text(2 + i).empty() ? m.numbers[i].eval(p) : def;
}

// FEAP's interactive plot kinds that have nothing to draw in a headless run:
// accepted (so a FEAPpv deck runs unchanged) and noted in the log.
bool interactiveKind(const std::string& k) {
  static const std::array<const char*, 14> kinds = {"wipe", "fram", "boun", "load", "node",
                                                    "elem", "axis", "rang", "fill", "outl",
                                                    "colo", "titl", "show", "scal"};
  return std::any_of(kinds.begin(), kinds.end(), [&](const char* w) { return k == w; });
}

// " at t = 3.5 (within step 421)" for an output of the motion between the
// states of the step in progress (solvers/DenseOutput.h); "" for a computed state.
std::string sampled(const State& shown, const State& computed) {
  if (shown.t == computed.t) return {};
  char buf[96];
  std::snprintf(buf, sizeof buf, " at t = %.6g (within step %d, which ends at t = %.6g)", shown.t,
                computed.step + 1, computed.t);
  return buf;
}

std::string label(const std::string& text) {
  std::string s = text;
  std::replace(s.begin(), s.end(), '_', ' ');
  return s;
}

class PrintNodalCommand final : public SolutionCommand {
 public:
  PrintNodalCommand(std::string name, std::string doc)
      : name_(std::move(name)), doc_(std::move(doc)) {}
  CommandSpec spec() const override {
    return solution(name_, doc_ + " Nodes n1 to n2 step inc; ,ALL or no numbers: every node.",
                    {word("option", "ALL"), num("n1", "first node"), num("n2", "last node", "n1"),
                     num("inc", "increment", "1")});
  }
  Flow run(const Macro& m, ProblemRun& r) const override {
    r.printNodal(m);
    return Flow::Next;
  }

 private:
  std::string name_, doc_;
};

class StreCommand final : public SolutionCommand {
 public:
  CommandSpec spec() const override {
    return solution("STREss",
                    "Print element section forces N, V, M (elements n1 to n2 step inc; ,ALL or "
                    "no numbers: all); STRE,HINGe: the table of softening hinges (at the element "
                    "ends: their joints).",
                    {word("option", "ALL or HINGe"), num("n1", "first element"),
                     num("n2", "last element", "n1"), num("inc", "increment", "1")});
  }
  Flow run(const Macro& m, ProblemRun& r) const override {
    if (m.option.rfind("hing", 0) == 0)
      r.printHinges();
    else
      r.printStresses(m);
    return Flow::Next;
  }
};

class TplotCommand final : public SolutionCommand {
 public:
  CommandSpec spec() const override {
    return solution("TPLOt",
                    "Time histories written every inc steps to <stem>_tplot.csv; records after "
                    "END up to a blank: disp,n,d  velo,n,d  acce,n,d  reac,n,d  stre,e,c "
                    "(c = 1 N, 2 V, 3 M)  ener  mome  arcl. Columns time, prop (load table 1's factor), with "
                    "several load tables prop_1, prop_2, ... (each table's), then the records'. ener gives kinetic, strain, contact, external, "
                    "total = kinetic + strain + contact - external, dissipated (plastic work, the "
                    "mid-point scheme's algorithmic and contact dissipation since the start) and "
                    "balance = total + dissipated, constant to the solver tolerance. mome gives momentum_x, "
                    "momentum_y and angular_momentum (about the origin, counterclockwise): under the "
                    "energy conserving scheme without loads, supports or contact, constant to the "
                    "solver tolerance. A later TPLOt of the "
                    "same run completes that file and starts <stem>_tplot_2.csv, and so on. A run that "
                    "fails or is interrupted keeps its rows as <stem>_tplot.failed.csv or "
                    "<stem>_tplot.interrupted.csv.",
                    {word("-", ""), num("inc", "output every inc steps", "1")}, "kind,n,d");
  }
  void bind(Macro& m, BindContext& ctx) const override {
    SolutionCommand::bind(m, ctx);
    if (written(m, 0)) {
      const int inc = m.numbers[0].evalInt(ctx.params(), "TPLOt increment");
      if (inc < 1) fail(m, 2, "the TPLOt increment must be 1 or more, got " + std::to_string(inc));
    }
    m.data = ctx.takeSet(m.record, "TPLOt records");
    for (const Record& rec : m.data) {
      const std::string k = commandKey(rec.text(0));
      if (k == "ener" || k == "arcl" || k == "mome") continue;
      if (k != "disp" && k != "velo" && k != "acce" && k != "reac" && k != "stre")
        throw DeckError(
            rec[0].loc,
            "unknown TPLOt quantity '" + rec.text(0) + "' (disp velo acce reac stre ener mome arcl)",
            rec.excerpt(rec[0].loc));
      if (rec.size() < 3)
        throw DeckError(rec.fieldLoc(rec.size()), "TPLOt record needs 'kind,number,component'",
                        rec.excerpt(rec.fieldLoc(rec.size())));
      for (std::size_t i = 1; i < 3; ++i) Expression::parse(rec[i]).evalInt(ctx.params(), "number");
    }
  }
  Flow run(const Macro& m, ProblemRun& r) const override {
    r.setTimeHistory(m);
    return Flow::Next;
  }
};

class PlotCommand final : public SolutionCommand {
 public:
  CommandSpec spec() const override {
    CommandSpec s;
    s.name = "PLOT";
    s.doc =
        "Headless pictures (SVG files, no display needed). PLOT,MESH: the undeformed mesh with "
        "supports and joints, <stem>_mesh.svg. PLOT,DEFOrmed,scale,chords: the deformed shape "
        "(displacements times scale; 0 or absent: automatic, 1 once they are large) with "
        "active and failed hinges, joints and the ground, <stem>_deformed_<step>.svg (after a "
        "loop whose last step passed its tmax: the motion at tmax, see TIME; a state already "
        "drawn, as in picture loops after the motion has come to rest, is not drawn again "
        "and the log says so once); members "
        "are drawn as curves leaving each node at its rotation, or as straight chords with "
        "chords = 1 (bars whose nodal rotations mean nothing). "
        "PLOT,CURVe,sx,sy with one data record after END naming two TPLOt columns: the "
        "x-y chart of that history, <stem>_<y>_vs_<x>.svg, written when the command runs and "
        "again, complete, at the end of the run (and overlaid across the runs of a SWEEp or "
        "of a top-level LOOP at the end of the deck). Labels: underscores print as blanks. "
        "PLOT,DEBRis: the debris picture, <stem>_debris.svg: the current state with the ground, "
        "the footprint and the SITE limits, the mass lying along the ground as a histogram, "
        "drawn again with the final state at the end of the run. "
        "FEAP's interactive kinds (WIPE, FRAMe, BOUNdary, LOAD, ...) are accepted and draw "
        "nothing.";
    s.fields = {word("kind", "MESH, DEFOrmed, CURVe or DEBRis"),
                num("p1", "DEFOrmed: displacement scale (0: automatic); CURVe: x scale factor", "0 / 1"),
                num("p2", "DEFOrmed: 1 straight chords; CURVe: y scale factor (-1 plots a reaction as a load)",
                    "0 / 1")};
    s.section = CommandSection::Solution;
    s.data = DataForm::Records;
    s.dataSyntax = "xcolumn ycolumn [xlabel ylabel]   (PLOT,CURVe only; e.g. disp_10_1 reac_10_1 u_[m] H_[kN])";
    return s;
  }

  void bind(Macro& m, BindContext& ctx) const override {
    SolutionCommand::bind(m, ctx);
    const std::string k = m.option.substr(0, 4);
    if (k == "mesh" || k == "defo" || k == "debr" || interactiveKind(k)) return;
    if (k != "curv")
      fail(m, 1, m.optionText.empty() ? "PLOT needs a kind: MESH, DEFOrmed, CURVe or DEBRis"
                                      : "unknown PLOT kind '" + m.optionText + "' (MESH, DEFOrmed, CURVe, DEBRis)");
    ctx.skipBlank();  // the blank record that ended the previous data set
    const Record& rec = ctx.take(m.record, "PLOT,CURVe record 'xcolumn ycolumn [xlabel ylabel]'");
    if (rec.size() < 2) failData(rec, rec.size(), "PLOT,CURVe needs 'xcolumn ycolumn [xlabel ylabel]'", columnHint());
    if (rec.size() == 3 || rec.size() > 4)
      failData(rec, rec.size() == 3 ? 2 : 4, "PLOT,CURVe labels come as a pair 'xlabel ylabel'",
               "write blanks inside a label as underscores: u_[m]");
    for (std::size_t i = 0; i < 2; ++i)
      if (resolveColumn(rec, i, ctx.params()).empty())
        failData(rec, i, "'" + rec.text(i) + "' is not a TPLOt column", columnHint());
    m.data.push_back(rec);
    ctx.skipBlank();
  }

  Flow run(const Macro& m, ProblemRun& r) const override {
    const std::string k = m.option.substr(0, 4);
    if (k == "mesh") {
      r.log() << "  PLOT   mesh: " << r.outputs().plotMesh(r.model()).filename().string() << "\n";
    } else if (k == "defo") {
      const double scale = value(m, 0, r.params(), 0.0);
      const bool chords = value(m, 1, r.params(), 0.0) != 0;
      RunOutputs& out = r.outputs();
      const State& shown = r.outputState();
      if (const auto path = out.plotDeformed(r.model(), shown, scale, !chords))
        r.log() << "  PLOT   deformed shape: " << path->filename().string()
                << sampled(shown, r.analysis().state()) << "\n";
      else if (out.deformedSkipped() == 1)  // said once
        r.log() << "  PLOT   deformed shape: no step since "
                << out.lastDeformed().filename().string()
                << (r.atRest() ? " (the motion is at rest)" : "")
                << ": it is not drawn again, nor by the later pictures of this state\n";
    } else if (k == "debr") {
      r.plotDebris();
    } else if (k == "curv") {
      const auto path = r.outputs().plotCurve(curveSpec(m, r.params()), r.history());
      r.log() << "  PLOT   curve: "
              << (path ? path->filename().string() : std::string("no time history yet, written at the end of the run"))
              << "\n";
    } else {
      r.log() << "  PLOT," << m.optionText << ": nothing to draw in a headless run\n";
    }
    return Flow::Next;
  }

  static CurveSpec curveSpec(const Macro& m, const Parameters& p) {
    const Record& rec = m.data.front();
    CurveSpec c;
    c.xColumn = resolveColumn(rec, 0, p);
    c.yColumn = resolveColumn(rec, 1, p);
    c.written = toLower(rec.text(0)) + " " + toLower(rec.text(1));
    c.xLabel = rec.size() >= 4 ? label(rec.text(2)) : c.xColumn;
    c.yLabel = rec.size() >= 4 ? label(rec.text(3)) : c.yColumn;
    // FEAP's convention: an empty or zero factor is the default 1.
    const double sx = value(m, 0, p, 1.0), sy = value(m, 1, p, 1.0);
    c.xScale = sx == 0 ? 1.0 : sx;
    c.yScale = sy == 0 ? 1.0 : sy;
    return c;
  }
};

class ParaViewCommand final : public SolutionCommand {
 public:
  CommandSpec spec() const override {
    CommandSpec s;
    s.name = "PVIEw";
    s.doc =
        "ParaView output (VTK XML): PVIEw writes the current state (the motion at tmax "
        "after a loop whose last step passed it, see TIME) as the next file "
        "<stem>_NNNN.vtu of the collection <stem>.pvd (deformed nodes; displacement, rotation, "
        "velocity, joint; per element N, V, M, material, hinge state, jump and position). "
        "PVIEw,,inc also writes every inc committed steps from then on, and the final state, "
        "so that a collapse plays as an animation; PVIEw,OFF stops that. The collection is "
        "<stem>.pvd.part until the run completes (<stem>.failed.pvd or <stem>.interrupted.pvd "
        "if it does not).";
    s.fields = {word("option", "OFF: stop the automatic output"),
                num("inc", "write every inc committed steps (0: now only)", "0")};
    s.section = CommandSection::Solution;
    return s;
  }
  void bind(Macro& m, BindContext& ctx) const override {
    SolutionCommand::bind(m, ctx);
    if (!m.option.empty() && m.option != "off") fail(m, 1, "PVIEw,,inc or PVIEw,OFF");
    if (m.option.empty() && m.has(0) && !m.record.text(2).empty() &&
        m.numbers[0].evalInt(ctx.params(), "PVIEw increment") < 0)
      fail(m, 2, "negative PVIEw increment");
  }
  Flow run(const Macro& m, ProblemRun& r) const override {
    if (m.option == "off") {
      r.outputs().setViewInterval(0);
      r.log() << "  PVIEw  off after " << r.outputs().viewsWritten() << " files\n";
      return Flow::Next;
    }
    const int inc = m.has(0) && !m.record.text(2).empty()
                        ? m.numbers[0].evalInt(r.params(), "PVIEw increment")
                        : 0;
    if (inc < 0) fail(m, 2, "negative PVIEw increment");
    r.outputs().setViewInterval(inc);
    const State& shown = r.outputState();
    const auto path = r.outputs().writeView(r.model(), shown);
    r.log() << "  PVIEw  "
            << (path ? path->filename().string() : std::string("state already written"))
            << sampled(shown, r.analysis().state());
    if (inc > 0) r.log() << ", then every " << inc << " steps";
    r.log() << "\n";
    return Flow::Next;
  }
};

}  // namespace

std::vector<std::unique_ptr<SolutionCommand>> outputCommands() {
  std::vector<std::unique_ptr<SolutionCommand>> out;
  out.push_back(std::make_unique<PrintNodalCommand>("DISPlacement", "Print nodal displacements."));
  out.push_back(std::make_unique<PrintNodalCommand>("VELOcity", "Print nodal velocities."));
  out.push_back(std::make_unique<PrintNodalCommand>("ACCEleration", "Print nodal accelerations."));
  out.push_back(std::make_unique<PrintNodalCommand>(
      "REACtion", "Print nodal reactions (the residual at every dof) and their sums."));
  out.push_back(std::make_unique<StreCommand>());
  out.push_back(std::make_unique<TplotCommand>());
  out.push_back(std::make_unique<PlotCommand>());
  out.push_back(std::make_unique<ParaViewCommand>());
  return out;
}

}  // namespace c2d
