// The solution commands of the BATCh language (deck language section 6): one
// small class each, with its declared spec, its bind step and its run step.
#include <cmath>
#include <sstream>

#include "macro/DeckParser.h"
#include "macro/Limits.h"
#include "macro/OutputCommands.h"
#include "macro/ProblemRun.h"
#include "macro/SolutionCommand.h"

namespace c2d {

namespace {

FieldSpec num(std::string name, std::string doc, std::string def = {}) {
  return {std::move(name), FieldKind::Expression, std::move(def), std::move(doc)};
}
FieldSpec word(std::string name, std::string doc, std::string def = {}) {
  return {std::move(name), FieldKind::Text, std::move(def), std::move(doc)};
}
CommandSpec solution(std::string name, std::string doc, std::vector<FieldSpec> fields,
                     std::string dataSyntax = {}) {
  CommandSpec s;
  s.name = std::move(name);
  s.doc = std::move(doc);
  s.fields = std::move(fields);
  s.section = CommandSection::Solution;
  if (!dataSyntax.empty()) {
    s.data = DataForm::Records;
    s.dataSyntax = std::move(dataSyntax);
  }
  return s;
}

[[noreturn]] void fail(const Macro& m, std::size_t field, const std::string& what) {
  throw DeckError(m.record.fieldLoc(field), what, m.record.excerpt(m.record.fieldLoc(field)));
}

std::string formatNumber(double v) {
  std::ostringstream s;
  s.precision(12);
  s << v;
  return s.str();
}

// Number i (record field 2 + i) when it is written, not empty.
bool written(const Macro& m, std::size_t i) { return m.has(i) && !m.record.text(2 + i).empty(); }

// A time step or minimum step written in number i must be positive; checked when
// the command is bound (before computing) and again when it runs (a parameter
// may have changed in between).
void checkPositive(const Macro& m, std::size_t i, const Parameters& p, const std::string& what) {
  if (!written(m, i)) return;
  const double v = m.numbers[i].eval(p);
  if (!(v > 0)) fail(m, 2 + i, what + " must be positive, got " + formatNumber(v));
}

// ---------------------------------------------------------------- control

class LoopCommand final : public SolutionCommand {
 public:
  CommandSpec spec() const override {
    return solution(
        "LOOP",
        "Repeat the commands up to the matching NEXT n times. A converged "
        "Newton iteration (TANG,,1 / UTAN,,1 / SOLV) leaves the innermost loop; so "
        "does one that diverges or stalls (its energy repeating with period one or "
        "two), which then counts as unconverged.",
        {word("label", "optional label matched by NEXT"), num("n", "repetitions", "1")});
  }
  void bind(Macro& m, BindContext& ctx) const override {
    if (m.has(0) && m.numbers[0].evalInt(ctx.params(), "loop count") < 0)
      fail(m, 2, "negative loop count");
  }
  Flow run(const Macro& m, ProblemRun& r) const override { return r.runLoop(m); }
};

class NextCommand final : public SolutionCommand {
 public:
  CommandSpec spec() const override {
    return solution("NEXT", "End of a LOOP.", {word("label", "label of the matching LOOP")});
  }
  Flow run(const Macro&, ProblemRun&) const override { return Flow::Next; }
};

class StopCommand final : public SolutionCommand {
 public:
  CommandSpec spec() const override { return solution("STOP", "End the run here.", {}); }
  Flow run(const Macro&, ProblemRun&) const override { return Flow::Stop; }
};

class ParaCommand final : public SolutionCommand {
 public:
  CommandSpec spec() const override {
    return solution("PARAmeter",
                    "Set a parameter: PARA,name,expression; or PARA alone with a block of "
                    "'name = expression' records after END, ended by a blank record.",
                    {word("name", "parameter name"), num("value", "expression")},
                    "name = expression");
  }
  void bind(Macro& m, BindContext& ctx) const override {
    if (m.optionText.empty()) {
      m.data = ctx.takeSet(m.record, "PARA block");
    } else if (!Parameters::validName(m.optionText)) {
      fail(m, 1, "invalid parameter name '" + m.optionText + "'");
    }
    apply(m, ctx.params());
  }
  Flow run(const Macro& m, ProblemRun& r) const override {
    apply(m, r.params());
    return Flow::Next;
  }

 private:
  static void apply(const Macro& m, Parameters& p) {
    if (!m.optionText.empty()) {
      p.set(toLower(m.optionText), m.has(0) ? m.numbers[0].eval(p) : 0.0);
      return;
    }
    for (const Record& rec : m.data) {
      const ParamAssign a = DeckParser::parseAssignment(rec);
      p.set(a.name, a.value.eval(p));
    }
  }
};

class MeshCommandMacro final : public SolutionCommand {
 public:
  CommandSpec spec() const override {
    return solution("MESH",
                    "Re-enter mesh input (loads, boundary conditions, materials, joints, "
                    "contact, gravity): mesh commands read after END up to an END record, or "
                    "from the file named.",
                    {word("file", "optional file holding the mesh commands")},
                    "mesh commands, END");
  }
  void bind(Macro& m, BindContext& ctx) const override {
    if (!m.optionText.empty()) return;
    for (;;) {
      const Record& rec = ctx.take(m.record, "mesh input ended by END");
      m.data.push_back(rec);
      if (rec.is("END")) break;
    }
  }
  Flow run(const Macro& m, ProblemRun& r) const override {
    r.reenterMesh(m);
    return Flow::Next;
  }
};

// ---------------------------------------------------------------- Newton

class TangCommand final : public SolutionCommand {
 public:
  explicit TangCommand(bool symmetric) : symmetric_(symmetric) {}
  CommandSpec spec() const override {
    if (symmetric_)
      return solution("TANGent",
                      "Form and factor the tangent; with ,1 one Newton iteration (residual, "
                      "solve, update); TANG,LINE,1 with a line search.",
                      {word("option", "LINE: line search"), num("n", "1: solve and update", "0")});
    return solution("UTANgent", "As TANG, for an unsymmetric tangent.",
                    {word("option", "LINE: line search"), num("n", "1: solve and update", "0")});
  }
  void bind(Macro& m, BindContext& ctx) const override {
    SolutionCommand::bind(m, ctx);
    if (!m.option.empty() && m.option.rfind("line", 0) != 0)
      fail(m, 1, "unknown option '" + m.optionText + "' (LINE is the only one)");
  }
  Flow run(const Macro& m, ProblemRun& r) const override {
    const bool update = m.has(0) && m.numbers[0].eval(r.params()) != 0;
    return r.newtonIteration(m, update, m.option.rfind("line", 0) == 0, symmetric_);
  }

 private:
  bool symmetric_;
};

class FormCommand final : public SolutionCommand {
 public:
  CommandSpec spec() const override {
    return solution("FORM",
                    "Form the residual at the current state and print its norm. FORM,LONG / "
                    "FORM,SHORt (FEAP): nodal tables printed with ten / five significant "
                    "digits from then on.",
                    {word("option", "LONG or SHORt")});
  }
  void bind(Macro& m, BindContext& ctx) const override {
    SolutionCommand::bind(m, ctx);
    if (!m.option.empty() && !keywordMatches(m.option, "LONG") &&
        !keywordMatches(m.option, "SHORt"))
      fail(m, 1, "unknown option '" + m.optionText + "' (LONG or SHORt)");
  }
  Flow run(const Macro& m, ProblemRun& r) const override {
    if (!m.option.empty()) {
      r.setLongFormat(keywordMatches(m.option, "LONG"));
      return Flow::Next;
    }
    return r.formResidual(m);
  }
};

class SolvCommand final : public SolutionCommand {
 public:
  CommandSpec spec() const override {
    return solution("SOLV", "Solve with the current factors for the current residual and update.",
                    {});
  }
  Flow run(const Macro& m, ProblemRun& r) const override { return r.solveOnly(m); }
};

class TolCommand final : public SolutionCommand {
 public:
  CommandSpec spec() const override {
    return solution("TOL",
                    "Convergence tolerances. TOL,,etol,rtol: a Newton step has converged when "
                    "|du.R| <= etol times the step's first value (FEAP's energy test, default "
                    "1e-16) or, with rtol > 0, when the residual norm ||R|| <= rtol times the "
                    "step's first one (default 0: off). TOL,ENER,value (FEAPpv): |du.R| below "
                    "value counts as converged.",
                    {word("option", "ENER: absolute energy value"), num("etol", "energy tolerance", "1e-16"),
                     num("rtol", "residual-force tolerance (0: off)", "0")});
  }
  void bind(Macro& m, BindContext& ctx) const override {
    SolutionCommand::bind(m, ctx);
    if (!m.option.empty() && m.option.rfind("ener", 0) != 0)
      fail(m, 1, "unknown option '" + m.optionText + "' (TOL,,etol,rtol or TOL,ENER,value)");
    if (m.option.empty()) checkPositive(m, 0, ctx.params(), "the tolerance");
  }
  Flow run(const Macro& m, ProblemRun& r) const override {
    auto value = [&](std::size_t i, double def) {
      return m.has(i) && !m.record.text(2 + i).empty() ? m.numbers[i].eval(r.params()) : def;
    };
    ConvergenceTest t = r.analysis().convergenceTest();
    if (!m.option.empty()) {
      const double zero = value(0, 0.0);
      if (!(zero >= 0)) fail(m, 2, "the energy value must not be negative");
      t.energyZero = zero;
    } else {
      const double etol = value(0, 1e-16), rtol = value(1, 0.0);
      if (!(etol > 0)) fail(m, 2, "the tolerance must be positive");
      if (!(rtol >= 0)) fail(m, 3, "the residual tolerance must not be negative");
      t.energyTol = etol;
      t.residualTol = rtol;
    }
    r.analysis().setConvergenceTest(t);
    return Flow::Next;
  }
};

// ---------------------------------------------------------------- time

class DtCommand final : public SolutionCommand {
 public:
  CommandSpec spec() const override {
    return solution("DT", "Time step.", {word("-", ""), num("dt", "time step")});
  }
  void bind(Macro& m, BindContext& ctx) const override {
    SolutionCommand::bind(m, ctx);
    if (!written(m, 0)) fail(m, 2, "DT needs the time step: DT,,dt");
    checkPositive(m, 0, ctx.params(), "the time step");
  }
  Flow run(const Macro& m, ProblemRun& r) const override {
    const double dt = m.has(0) ? m.numbers[0].eval(r.params()) : 0.0;
    if (!(dt > 0)) fail(m, 2, "the time step must be positive");
    r.setDt(dt);
    return Flow::Next;
  }
};

class TimeCommand final : public SolutionCommand {
 public:
  CommandSpec spec() const override {
    return solution("TIME",
                    "Commit the converged step and advance the time by dt; with tmax the "
                    "enclosing loop ends once the time has reached tmax. TIME,REST,tmax,ratio,"
                    "hold: the loop also ends (without a step) once the motion has come to rest: "
                    "the kinetic energy at most ratio of its peak for the last hold time units "
                    "(the log says when).",
                    {word("option", "REST: end the loop at rest"),
                     num("tmax", "end time (optional)"),
                     num("ratio", "REST: kinetic energy over its peak", "1e-5"),
                     num("hold", "REST: for this long", "0.5")});
  }
  void bind(Macro& m, BindContext& ctx) const override {
    SolutionCommand::bind(m, ctx);
    if (!m.option.empty() && m.option.rfind("rest", 0) != 0)
      fail(m, 1, "TIME,,tmax or TIME,REST,tmax,ratio,hold");
    if (m.option.empty() && (written(m, 1) || written(m, 2)))
      fail(m, written(m, 1) ? 3 : 4, "ratio and hold belong to TIME,REST,tmax,ratio,hold");
    rest(m, ctx.params());
  }
  Flow run(const Macro& m, ProblemRun& r) const override {
    const bool hasMax = written(m, 0);
    return r.advanceTime(
        m, hasMax ? std::optional<double>(m.numbers[0].eval(r.params())) : std::nullopt,
        rest(m, r.params()));
  }

 private:
  static std::optional<ProblemRun::Rest> rest(const Macro& m, const Parameters& p) {
    if (m.option.empty()) return std::nullopt;
    ProblemRun::Rest r;
    if (written(m, 1)) r.ratio = m.numbers[1].eval(p);
    if (written(m, 2)) r.hold = m.numbers[2].eval(p);
    if (!(r.ratio > 0 && r.ratio < 1))
      fail(m, 3, "the kinetic energy ratio of TIME,REST is between 0 and 1, got " +
                     formatNumber(r.ratio));
    if (!(r.hold >= 0))
      fail(m, 4, "the hold time of TIME,REST is 0 or more, got " + formatNumber(r.hold));
    return r;
  }
};

class BackCommand final : public SolutionCommand {
 public:
  CommandSpec spec() const override {
    return solution("BACK", "Return to the last committed step (optionally with a new dt).",
                    {word("-", ""), num("dt", "new time step (optional)")});
  }
  void bind(Macro& m, BindContext& ctx) const override {
    SolutionCommand::bind(m, ctx);
    checkPositive(m, 0, ctx.params(), "the new time step");
  }
  Flow run(const Macro& m, ProblemRun& r) const override {
    checkPositive(m, 0, r.params(), "the new time step");
    r.analysis().back();
    if (written(m, 0)) r.setDt(m.numbers[0].eval(r.params()));
    r.log() << "  BACK  to t = " << r.analysis().state().t << "\n";
    return Flow::Next;
  }
};

class PropCommand final : public SolutionCommand {
 public:
  CommandSpec spec() const override {
    return solution("PROPortional",
                    "Proportional load table, data after END: a blank record (ramp p = t); "
                    "'1 k tmin tmax a1 a2 a3 a4 a5' (p = a1 + a2*tau + a3*sin(a4*tau + a5)^k, "
                    "tau = t - tmin, on [tmin, tmax]); or '2' then 't p' pairs, blank.",
                    {word("-", ""), num("n", "table number", "1")},
                    "type ... (see the command's doc)");
  }
  void bind(Macro& m, BindContext& ctx) const override {
    SolutionCommand::bind(m, ctx);
    int table = 1;
    if (written(m, 0)) {
      table = m.numbers[0].evalInt(ctx.params(), "table number");
      if (table < 0) fail(m, 2, "a proportional load table number is 0 or positive");
      checkNumber(m.record, 2, std::max(table, 1), DeckLimits::kMaxLoadTables,
                  "proportional load table");
    }
    ctx.loadTables().insert(std::max(table, 1));
    const Record& first = ctx.take(m.record, "proportional load data");
    m.data.push_back(first);
    if (first.blank()) return;
    const Expression type = Expression::parse(first[0]);
    const int t = type.evalInt(ctx.params(), "proportional load type");
    if (t == 1) {
      ctx.skipBlank();
    } else if (t == 2) {
      // The times of a table increase strictly: p(t) is interpolated between them.
      bool started = false;
      double last = 0;
      for (const Record& rec : ctx.takeSet(m.record, "proportional load table")) {
        m.data.push_back(rec);
        for (std::size_t i = 0; i + 1 < rec.size(); i += 2) {
          const double time = Expression::parse(rec[i]).eval(ctx.params());
          if (started && !(time > last))
            throw DeckError(rec[i].loc,
                            "time " + formatNumber(time) + " of the proportional load table " +
                                (time == last ? "repeats the one before it"
                                              : "comes after the later time " + formatNumber(last)),
                            rec.excerpt(rec[i].loc), "give the 't p' pairs in increasing time");
          started = true;
          last = time;
        }
      }
    } else {
      throw DeckError(first[0].loc,
                      "unknown proportional load type " + std::to_string(t) +
                          " (1: formula, 2: table, blank record: ramp)",
                      first.excerpt(first[0].loc));
    }
  }
  Flow run(const Macro& m, ProblemRun& r) const override {
    r.setProportionalLoad(m);
    return Flow::Next;
  }
};

class DynaCommand final : public SolutionCommand {
 public:
  explicit DynaCommand(bool feapName) : feapName_(feapName) {}
  CommandSpec spec() const override {
    if (feapName_)
      return solution("TRANsient", "FEAPpv's name for DYNA: TRAN,NEWMark,beta,gamma / TRAN,OFF.",
                      {word("scheme", "NEWMark, ENERgy or OFF"), num("p1", ""), num("p2", "")});
    return solution("DYNAmic",
                    "Time integrator: DYNA,NEWMark,beta,gamma (default 0.25, 0.5); "
                    "DYNA,ENERgy,alpha,beta: energy conserving (0, 0) or decaying (alpha, beta in "
                    "(0, 1/2]) mid-point scheme; DYNA,OFF: static.",
                    {word("scheme", "NEWMark, ENERgy or OFF"), num("p1", "beta / alpha"),
                     num("p2", "gamma / beta")});
  }
  void bind(Macro& m, BindContext& ctx) const override {
    SolutionCommand::bind(m, ctx);
    const std::string k = m.option.substr(0, 4);
    if (k != "newm" && k != "ener" && k != "off" && k != "")
      fail(m, 1, "unknown time integrator '" + m.optionText + "' (NEWMark, ENERgy, OFF)");
    if (k == "ener")
      for (std::size_t i = 0; i < 2 && i < m.numbers.size(); ++i) {
        const double v = m.numbers[i].eval(ctx.params());
        if (v < 0 || v > 0.5)
          fail(m, 2 + i, "alpha and beta of the mid-point scheme lie in [0, 1/2]");
      }
  }
  Flow run(const Macro& m, ProblemRun& r) const override {
    const std::string k = m.option.substr(0, 4);
    auto value = [&](std::size_t i, double def) {
      return m.has(i) && !m.record.text(2 + i).empty() ? m.numbers[i].eval(r.params()) : def;
    };
    TimeIntegrator ti;
    if (k == "off")
      ti = TimeIntegrator::statics();
    else if (k == "ener")
      ti = TimeIntegrator::midPoint(value(0, 0.0), value(1, 0.0));
    else
      ti = TimeIntegrator::newmark(value(0, 0.25), value(1, 0.5));
    r.setIntegrator(ti);
    return Flow::Next;
  }

 private:
  bool feapName_;
};

class AutoCommand final : public SolutionCommand {
 public:
  CommandSpec spec() const override {
    return solution("AUTOmatic",
                    "Automatic step cutting: AUTO,CUT,dtmin: a Newton loop that ends unconverged, "
                    "diverges or stalls (or a singular tangent) returns to the last committed "
                    "step, halves dt and "
                    "retries, down to dtmin; dt grows back after converged steps. "
                    "AUTO,CUT,dtmin,1: a dynamic step whose predicted start diverges is cut too "
                    "(otherwise it starts again from the committed state). AUTO,OFF.",
                    {word("mode", "CUT or OFF"), num("dtmin", "smallest step", "dt/1024"),
                     num("pred", "1: a diverging predicted start cuts the step", "0")});
  }
  void bind(Macro& m, BindContext& ctx) const override {
    SolutionCommand::bind(m, ctx);
    const std::string k = m.option.substr(0, 3);
    if (k != "cut" && k != "off") fail(m, 1, "AUTO,CUT,dtmin or AUTO,OFF");
    // dtmin <= 0 would let the cutting halve the step forever.
    if (k == "cut") {
      checkPositive(m, 0, ctx.params(), "the smallest step dtmin");
      predictionFlag(m, ctx.params());
    }
  }
  Flow run(const Macro& m, ProblemRun& r) const override {
    if (m.option.rfind("off", 0) == 0) {
      r.setStepCutting(false, 0);
    } else {
      checkPositive(m, 0, r.params(), "the smallest step dtmin");
      r.setStepCutting(true,
                       m.has(0) && !m.record.text(2).empty() ? m.numbers[0].eval(r.params()) : 0.0,
                       predictionFlag(m, r.params()));
    }
    return Flow::Next;
  }

 private:
  // The pred field: 0 (default) or 1.
  static bool predictionFlag(const Macro& m, const Parameters& p) {
    if (!written(m, 1)) return false;
    const double v = m.numbers[1].eval(p);
    if (v != 0 && v != 1) fail(m, 3, "AUTO,CUT,dtmin,pred: pred is 0 or 1, got " + formatNumber(v));
    return v == 1;
  }
};

class ArclCommand final : public SolutionCommand {
 public:
  CommandSpec spec() const override {
    return solution(
        "ARCLength",
        "Path following, data records after END as FEAPpv reads them: first 'ndamp' (the "
        "damping flag, 1: none; 0 is accepted, with a warning, as no damping is applied), "
        "then for kfl 4 or 5 (displacement control) 'node dof increment'. kfl 1, 2, 3 (0 "
        "counts as 2): cylindrical arc length set by the first step, whose load increment is "
        "its time step (FEAPpv) or [ext] dlambda0 written after ndamp, 'ndamp dlambda0'. "
        "Accepted too: 'node dof increment' alone, and a lone 'dlambda0' other than 0 or 1 "
        "(with a warning). ARCL,OFF.",
        {word("option", "OFF to switch off"),
         num("kfl", "1, 2, 3 arc length; 4, 5 displacement control", "2"),
         num("lfl", "0 (1, changing a running arc length, is not available)", "0")},
        "ndamp [dlambda0], then node dof increment (kfl 4, 5)");
  }
  void bind(Macro& m, BindContext& ctx) const override {
    SolutionCommand::bind(m, ctx);
    if (m.option == "off") return;
    if (!m.option.empty())
      fail(m, 1, "unknown option '" + m.optionText + "' (ARCL,,kfl or ARCL,OFF)");
    const int kfl = kflag(m, ctx.params());
    if (kfl < 1 || kfl > 5)
      fail(m, 2, "ARCL kfl must be 1, 2, 3 (arc length) or 4, 5 (displacement control)");
    if (written(m, 1) && m.numbers[1].evalInt(ctx.params(), "ARCL lfl") != 0)
      fail(m, 3, "ARCL lfl = 1 (new arc length for a running analysis) is not available");
    const Record& first = ctx.take(m.record, "ARCL data");
    if (first.blank())
      throw DeckError(first.loc, "ARCL data record expected: 'ndamp' (1: no damping)",
                      m.record.lineText());
    auto values = [&](const Record& rec, std::size_t want, const char* what) {
      if (rec.size() < want)
        throw DeckError(rec.fieldLoc(rec.size()), std::string("ARCL needs '") + what + "'",
                        rec.excerpt(rec.fieldLoc(rec.size())));
      std::vector<double> v;
      for (std::size_t i = 0; i < rec.size(); ++i)
        v.push_back(Expression::parse(rec[i]).eval(ctx.params()));
      return v;
    };
    const std::vector<double> v = values(first, 1, "ndamp");
    auto checkDamping = [&](double ndamp) {
      if (ndamp != 0 && ndamp != 1)
        throw DeckError(first[0].loc,
                        "the damping flag ndamp is 0 or 1, got " + formatNumber(ndamp),
                        first.excerpt(first[0].loc), "FEAPpv's first ARCL record is 'ndamp'");
      if (ndamp == 0)
        ctx.warn(first[0].loc,
                 "ndamp = 0: the load increments of the arc length are not damped here",
                 first.excerpt(first[0].loc));
    };
    if (kfl >= 4) {
      if (first.size() >= 3) {
        m.data.push_back(first);  // 'node dof increment' without the damping record
      } else {
        checkDamping(v[0]);
        const Record& rec = ctx.take(m.record, "ARCL record 'node dof increment'");
        values(rec, 3, "node dof increment");
        m.data.push_back(rec);
      }
    } else if (v.size() >= 2) {
      checkDamping(v[0]);
      m.data.push_back(first);  // ndamp dlambda0
    } else if (v[0] == 0 || v[0] == 1) {
      checkDamping(v[0]);  // FEAPpv: the first increment is the first step's dt
    } else {
      ctx.warn(first[0].loc,
               "a lone value other than 0 or 1 is read as the first load increment dlambda0; "
               "FEAPpv reads this record as the damping flag: write 'ndamp dlambda0', e.g. '1 " +
                   first[0].text + "'",
               first.excerpt(first[0].loc));
      m.data.push_back(first);
    }
    ctx.skipBlank();
  }
  Flow run(const Macro& m, ProblemRun& r) const override {
    r.setPathFollowing(m);
    return Flow::Next;
  }
  // FEAP's kfl, 0 counting as 2.
  static int kflag(const Macro& m, const Parameters& p) {
    const int k = written(m, 0) ? m.numbers[0].evalInt(p, "ARCL kfl") : 0;
    return k == 0 ? 2 : k;
  }
};

// ---------------------------------------------------------------- output

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
                    "no numbers: all); STRE,HINGe: the table of softening hinges (at the element ends: their joints).",
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

class HingeToJointCommand final : public SolutionCommand {
 public:
  CommandSpec spec() const override {
    return solution("HINGe2joint",
                    "End of the failure phase: every activated softening hinge becomes a revolute "
                    "joint (at the element end nearer the hinge; its jump becomes the joint's "
                    "relative rotation), every element becomes an elastic geometrically exact "
                    "(FINIte) beam starting with its current section forces (the paper); the "
                    "current displacements and velocities are kept. HINGe2joint,INELastic: the "
                    "same, but the members keep their hardening and softening laws and history "
                    "in FINIte kinematics, so new hinges form, fail into joints and rupture "
                    "during the collapse.",
                    {word("option", "INELastic: members keep their laws")});
  }
  void bind(Macro& m, BindContext& ctx) const override {
    SolutionCommand::bind(m, ctx);
    if (!m.option.empty() && !keywordMatches(m.optionText, "INELastic"))
      fail(m, 1, "unknown option '" + m.optionText + "' (INELastic is the only one)");
  }
  Flow run(const Macro& m, ProblemRun& r) const override {
    r.hingesToJoints(m, m.option.empty() ? MemberLaws::Elastic : MemberLaws::Inelastic);
    return Flow::Next;
  }
};

class RemoveCommand final : public SolutionCommand {
 public:
  CommandSpec spec() const override {
    return solution("REMOve",
                    "REMOve,ELEMents,n1,n2,inc,td: elements n1 to n2 step inc leave the model now "
                    "(the converged state is committed first), their forces on the rest released "
                    "linearly over td (0 or empty: at once), as a BLASt record at the current "
                    "time does (see BLASt): the GSA alternate-path column removal.",
                    {word("option", "ELEMents"), num("n1", "first element"),
                     num("n2", "last element", "n1"), num("inc", "increment", "1"),
                     num("td", "release time of the forces", "0")});
  }
  void bind(Macro& m, BindContext& ctx) const override {
    SolutionCommand::bind(m, ctx);
    if (!keywordMatches(m.optionText, "ELEMents"))
      fail(m, 1, m.optionText.empty() ? "REMOve needs ELEMents and the element numbers"
                                      : "unknown option '" + m.optionText + "' (ELEMents)");
    if (!written(m, 0)) fail(m, 2, "REMOve,ELEMents needs the first element n1");
    checkPositive(m, 0, ctx.params(), "the first element");
    if (written(m, 3) && !(m.numbers[3].eval(ctx.params()) >= 0))
      fail(m, 5, "the release time td must be zero or positive");
  }
  Flow run(const Macro& m, ProblemRun& r) const override {
    r.removeMembers(m);
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

// ---------------------------------------------------------------- restart

class SaveCommand final : public SolutionCommand {
 public:
  CommandSpec spec() const override {
    return solution("SAVE",
                    "Commit the converged step and write the restart file <name>.rst in the "
                    "output directory (default name: the run's stem): the model as it is now "
                    "(joints, rebuilt elements, re-entered mesh data), every element's history, "
                    "the state, the integrator, tolerance, load tables, path following and "
                    "energy bookkeeping. Written as <name>.rst.part and renamed when complete. "
                    "A run restarted from it (REST) repeats the uninterrupted run bit for bit.",
                    {word("name", "restart file name (optional; .rst is added)")});
  }
  Flow run(const Macro& m, ProblemRun& r) const override {
    r.saveRestart(m);
    return Flow::Next;
  }
};

class RestCommand final : public SolutionCommand {
 public:
  CommandSpec spec() const override {
    return solution("RESTart",
                    "Read the restart file <name>.rst from the output directory (default name: "
                    "the run's stem) written by SAVE: the model and the analysis state are "
                    "replaced by the saved ones (the deck's mesh input is still read and checked "
                    "first), and the following commands continue from the saved step. Output "
                    "commands (TPLOt, PLOT, PVIEw) are not saved: give them again after REST. A "
                    "truncated, corrupted or foreign file is an error, and so is a file written for "
                    "another model (the deck's node coordinates, elements, materials, boundary "
                    "codes or loads differ from those the saving deck started with).",
                    {word("name", "restart file name (optional; .rst is added)")});
  }
  void bind(Macro& m, BindContext& ctx) const override {
    SolutionCommand::bind(m, ctx);
    ctx.noteRestart();
  }
  Flow run(const Macro& m, ProblemRun& r) const override {
    r.restoreRestart(m);
    return Flow::Next;
  }
};

}  // namespace

// ---------------------------------------------------------------- plumbing

const Record& BindContext::take(const Record& who, const char* what) {
  if (atEnd())
    throw DeckError(who.loc, std::string("missing ") + what + " after the BATCh END",
                    who.lineText());
  return data_[pos_++];
}

std::vector<Record> BindContext::takeSet(const Record& who, const char* what) {
  std::vector<Record> out;
  for (;;) {
    if (atEnd())
      throw DeckError(
          who.loc, std::string("the ") + what + " after the BATCh END must end with a blank record",
          who.lineText());
    const Record& rec = data_[pos_++];
    if (rec.blank()) break;
    out.push_back(rec);
  }
  return out;
}

void SolutionCommand::bind(Macro& m, BindContext& ctx) const {
  for (const Expression& e : m.numbers) e.eval(ctx.params());
}

bool Macro::newtonLoop() const {
  for (const Macro& b : body)
    if (b.is("tang") || b.is("utan") || b.is("solv")) return true;
  return false;
}

SolutionCommands::SolutionCommands() : registry_("Solution commands (BATCh ... END)") {
  add(std::make_unique<LoopCommand>());
  add(std::make_unique<NextCommand>());
  add(std::make_unique<TangCommand>(true));
  add(std::make_unique<TangCommand>(false));
  add(std::make_unique<FormCommand>());
  add(std::make_unique<SolvCommand>());
  add(std::make_unique<TolCommand>());
  add(std::make_unique<DtCommand>());
  add(std::make_unique<TimeCommand>());
  add(std::make_unique<BackCommand>());
  add(std::make_unique<PropCommand>());
  add(std::make_unique<ArclCommand>());
  add(std::make_unique<AutoCommand>());
  add(std::make_unique<DynaCommand>(false));
  add(std::make_unique<DynaCommand>(true));
  add(std::make_unique<PrintNodalCommand>("DISPlacement", "Print nodal displacements."));
  add(std::make_unique<PrintNodalCommand>("VELOcity", "Print nodal velocities."));
  add(std::make_unique<PrintNodalCommand>("ACCEleration", "Print nodal accelerations."));
  add(std::make_unique<PrintNodalCommand>("REACtion",
                                          "Print nodal reactions (the residual at every dof) "
                                          "and their sums."));
  add(std::make_unique<StreCommand>());
  add(std::make_unique<TplotCommand>());
  add(makePlotCommand());
  add(makeParaViewCommand());
  add(std::make_unique<MeshCommandMacro>());
  add(std::make_unique<HingeToJointCommand>());
  add(std::make_unique<RemoveCommand>());
  add(std::make_unique<SaveCommand>());
  add(std::make_unique<RestCommand>());
  add(std::make_unique<ParaCommand>());
  add(std::make_unique<StopCommand>());
}

void SolutionCommands::add(std::unique_ptr<SolutionCommand> c) {
  registry_.add(c->spec());
  commands_.push_back(std::move(c));
}

const SolutionCommand* SolutionCommands::find(const std::string& word) const {
  const CommandSpec* s = registry_.find(word);
  if (!s) return nullptr;
  for (const auto& c : commands_)
    if (c->spec().key() == s->key()) return c.get();
  return nullptr;
}

namespace {

Macro makeMacro(const Record& rec, const SolutionCommands& table) {
  Macro m;
  m.record = rec;
  m.command = table.find(rec.text(0));
  if (!m.command) {
    const std::string hint = table.registry().suggest(rec.text(0));
    throw DeckError(rec[0].loc, "unknown solution command '" + rec.text(0) + "'",
                    rec.excerpt(rec[0].loc), hint);
  }
  m.key = m.command->spec().key();
  m.optionText = rec.text(1);
  m.option = toLower(m.optionText);
  // Written fields the command does not read are errors, not ignored: an
  // option word where it takes none ("-"), a value beyond its last field.
  const CommandSpec& spec = m.command->spec();
  auto syntax = [&spec] {
    std::string s = "the command is " + spec.name.substr(0, 4);
    for (std::size_t i = 0; i < spec.fields.size(); ++i)
      s += "," + (i == 0 && spec.fields[0].name == "-" ? std::string() : spec.fields[i].name);
    return s;
  };
  if (!m.optionText.empty() && !spec.fields.empty() && spec.fields[0].name == "-")
    throw DeckError(rec[1].loc,
                    spec.name.substr(0, 4) + " takes no option word, got '" + m.optionText + "'",
                    rec.excerpt(rec[1].loc), syntax());
  for (std::size_t i = std::max<std::size_t>(spec.fields.size() + 1, 2); i < rec.size(); ++i)
    if (!rec.text(i).empty())
      throw DeckError(rec[i].loc, "a field beyond the command's last one would be ignored",
                      rec.excerpt(rec[i].loc), syntax());
  for (std::size_t i = 2; i < rec.size(); ++i) m.numbers.push_back(Expression::parse(rec[i]));
  return m;
}

// Builds the command tree with LOOP/NEXT matched; returns at the NEXT closing `loop`.
// depth: loops around this list (bounded, so that the recursion here, in
// binding and in running stays shallow).
std::vector<Macro> buildTree(const std::vector<Record>& recs, std::size_t& pos,
                             const SolutionCommands& table, Macro* loop, int depth) {
  std::vector<Macro> out;
  while (pos < recs.size()) {
    const Record& rec = recs[pos++];
    if (rec.blank()) continue;
    Macro m = makeMacro(rec, table);
    if (m.is("next")) {
      if (!loop) throw DeckError(rec.loc, "NEXT without a matching LOOP", rec.lineText());
      if (!m.optionText.empty() && !loop->optionText.empty() && m.option != loop->option)
        throw DeckError(rec[1].loc,
                        "NEXT," + m.optionText + " closes LOOP," + loop->optionText + " (" +
                            loop->record.loc.str() + ")",
                        rec.excerpt(rec[1].loc));
      loop->next = rec;
      return out;
    }
    if (m.is("loop")) {
      if (depth >= DeckLimits::kMaxLoopDepth)
        throw DeckError(
            rec[0].loc,
            "LOOP nested more than " + std::to_string(DeckLimits::kMaxLoopDepth) + " deep",
            rec.excerpt(rec[0].loc));
      m.body = buildTree(recs, pos, table, &m, depth + 1);
      if (m.next.blank()) throw DeckError(rec.loc, "LOOP without a matching NEXT", rec.lineText());
    }
    out.push_back(std::move(m));
  }
  return out;
}

void bindTree(std::vector<Macro>& list, BindContext& ctx) {
  for (Macro& m : list) {
    m.command->bind(m, ctx);
    if (m.is("loop")) bindTree(m.body, ctx);
  }
}

}  // namespace

std::vector<Macro> bindBatch(const std::vector<Record>& commands, const std::vector<Record>& data,
                             const SolutionCommands& table, Parameters& params, BindFacts* facts) {
  std::size_t pos = 0;
  std::vector<Macro> tree = buildTree(commands, pos, table, nullptr, 0);
  BindContext ctx(data, params, facts);
  bindTree(tree, ctx);
  while (!ctx.atEnd()) {
    const Record& rec = ctx.peek();
    if (!rec.blank())
      throw DeckError(rec.loc, "data record not read by any solution command", rec.lineText());
    ctx.skipBlank();
  }
  return tree;
}

}  // namespace c2d
