// The solution commands of time and load stepping: DT, TIME, BACK, PROP,
// ARCLength, AUTO, DYNAmic (and its TRANsient alias).
#include <cmath>

#include "macro/deck/Limits.h"
#include "macro/run/ProblemRun.h"
#include "macro/solution/SolutionCommandKit.h"

namespace c2d {

namespace {

using namespace batchspec;

// PROP: the law of a proportional load table, set in the analysis and logged.
void setProportionalLoad(const Macro& m, Parameters& params_, Analysis& analysis,
                         std::ostream& log_) {
  const Record& first = m.data.front();
  const int table =
      m.has(0) && !m.record.text(2).empty() ? m.numbers[0].evalInt(params_, "table number") : 1;
  if (first.blank()) {
    analysis.setLoadFunction(table, ProportionalLoad::ramp());
    log_ << "  PROP   table " << table << ": ramp p = t\n";
    return;
  }
  auto value = [&](const Record& r, std::size_t i) {
    return i < r.size() ? Expression::parse(r[i]).eval(params_) : 0.0;
  };
  const int type = static_cast<int>(value(first, 0));
  if (type == 1) {
    std::array<double, 5> a{};
    for (int i = 0; i < 5; ++i) a[i] = value(first, 4 + i);
    const int k = static_cast<int>(value(first, 1));
    analysis.setLoadFunction(
        table, ProportionalLoad::formula(k == 0 ? 1 : k, value(first, 2), value(first, 3), a));
    log_ << "  PROP   table " << table << ": type 1\n";
    return;
  }
  std::vector<std::pair<double, double>> pts;
  for (std::size_t r = 1; r < m.data.size(); ++r)
    for (std::size_t i = 0; i + 1 < m.data[r].size(); i += 2)
      pts.emplace_back(value(m.data[r], i), value(m.data[r], i + 1));
  analysis.setLoadFunction(table, ProportionalLoad::table(std::move(pts)));
  log_ << "  PROP   table " << table << ": type 2\n";
}

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
                    "enclosing loop ends once the time has reached tmax. Under step cutting "
                    "(AUTO,CUT) the loop's last step is shortened to end on tmax when the loop "
                    "ends a phase: when the first command after it, outputs (PLOT, PVIEw, "
                    "TPLOt, DISP, VELO, ACCE, REAC, STRE, PARA) passed over, changes the model "
                    "or the analysis (MESH, HINGe2joint, REMOve, DYNAmic, DT, ...), or the run "
                    "ends there. Before another TIME (a picture loop's next pass) or a SAVE it "
                    "is not: the loop ends with the step that passes tmax, and the pictures and "
                    "ParaView frames until the next step show the motion at tmax, interpolated "
                    "between the step's states (printed tables stay those of the computed "
                    "step); so the number and times of the pictures never change the steps. "
                    "TIME,REST,tmax,ratio,hold: the loop also ends (without a "
                    "step) once the motion has come to rest: the kinetic energy at most ratio "
                    "of its peak for the last hold time units (the log says when).",
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
  static std::optional<RunWatches::Rest> rest(const Macro& m, const Parameters& p) {
    if (m.option.empty()) return std::nullopt;
    RunWatches::Rest r;
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
    setProportionalLoad(m, r.params(), r.analysis(), r.log());
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
                    "(0, 1/2]) mid-point scheme; DYNA,OFF: static. A converged step is "
                    "committed under the rule it was solved with; a step that TIME began and no "
                    "iteration solved yet begins again under the new one.",
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
    r.setIntegrator(m, ti);
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

}  // namespace

std::vector<std::unique_ptr<SolutionCommand>> timeCommands() {
  std::vector<std::unique_ptr<SolutionCommand>> out;
  out.push_back(std::make_unique<DtCommand>());
  out.push_back(std::make_unique<TimeCommand>());
  out.push_back(std::make_unique<BackCommand>());
  out.push_back(std::make_unique<PropCommand>());
  out.push_back(std::make_unique<ArclCommand>());
  out.push_back(std::make_unique<AutoCommand>());
  out.push_back(std::make_unique<DynaCommand>(false));
  out.push_back(std::make_unique<DynaCommand>(true));
  return out;
}

}  // namespace c2d
