// The solution commands that steer the run: LOOP and NEXT, PARAmeter,
// MESH re-entry, STOP.
#include "macro/deck/DeckParser.h"
#include "macro/run/ProblemRun.h"
#include "macro/solution/SolutionCommandKit.h"

namespace c2d {

namespace {

using namespace batchspec;

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
      p.assign(toLower(m.optionText), m.has(0) ? m.numbers[0].eval(p) : 0.0, m.record[1]);
      return;
    }
    for (const Record& rec : m.data) {
      const ParamAssign a = DeckParser::parseAssignment(rec);
      p.assign(a.name, a.value.eval(p), rec[0]);
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

}  // namespace

std::vector<std::unique_ptr<SolutionCommand>> controlCommands() {
  std::vector<std::unique_ptr<SolutionCommand>> out;
  out.push_back(std::make_unique<LoopCommand>());
  out.push_back(std::make_unique<NextCommand>());
  out.push_back(std::make_unique<ParaCommand>());
  out.push_back(std::make_unique<MeshCommandMacro>());
  out.push_back(std::make_unique<StopCommand>());
  return out;
}

}  // namespace c2d
