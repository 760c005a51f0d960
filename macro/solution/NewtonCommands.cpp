// The solution commands of the Newton iteration: TANGent and UTANgent, FORM,
// SOLV, TOL.
#include "macro/run/ProblemRun.h"
#include "macro/solution/SolutionCommandKit.h"

namespace c2d {

namespace {

using namespace batchspec;

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

}  // namespace

std::vector<std::unique_ptr<SolutionCommand>> newtonCommands() {
  std::vector<std::unique_ptr<SolutionCommand>> out;
  out.push_back(std::make_unique<TangCommand>(true));
  out.push_back(std::make_unique<TangCommand>(false));
  out.push_back(std::make_unique<FormCommand>());
  out.push_back(std::make_unique<SolvCommand>());
  out.push_back(std::make_unique<TolCommand>());
  return out;
}

}  // namespace c2d
