// The solution commands of restart files: SAVE and REST.
#include "macro/run/ProblemRun.h"
#include "macro/solution/SolutionCommandKit.h"

namespace c2d {

namespace {

using namespace batchspec;

// A restart file lies in the output directory: its name is a plain file name,
// so that SAVE writes nowhere else (no "../x", no "/abs").
void checkRestartName(const Macro& m) {
  const std::string& name = m.optionText;
  if (name.find('/') != std::string::npos || name == "." || name == "..")
    fail(m, 1,
         "restart file name '" + name +
             "' leads out of the output directory: give a plain name (the file is <name>.rst "
             "in the directory of -o)");
}

class SaveCommand final : public SolutionCommand {
 public:
  CommandSpec spec() const override {
    return solution("SAVE",
                    "Commit the converged step and write the restart file <name>.rst in the "
                    "output directory (default name: the run's stem): the model as it is now "
                    "(joints, rebuilt elements, re-entered mesh data), every element's history, "
                    "the state, the integrator, tolerance, load tables, path following and "
                    "energy bookkeeping. Written through a temporary <name>.rst.XXXXXX.part and renamed when complete. "
                    "A run restarted from it (REST) repeats the uninterrupted run bit for bit.",
                    {word("name", "restart file name in the output directory (optional; .rst "
                                  "is added; no '/')")});
  }
  void bind(Macro& m, BindContext& ctx) const override {
    SolutionCommand::bind(m, ctx);
    checkRestartName(m);
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
                    {word("name", "restart file name in the output directory (optional; .rst "
                                  "is added; no '/')")});
  }
  void bind(Macro& m, BindContext& ctx) const override {
    SolutionCommand::bind(m, ctx);
    checkRestartName(m);
    ctx.noteRestart();
  }
  Flow run(const Macro& m, ProblemRun& r) const override {
    r.restoreRestart(m);
    return Flow::Next;
  }
};

}  // namespace

std::vector<std::unique_ptr<SolutionCommand>> restartCommands() {
  std::vector<std::unique_ptr<SolutionCommand>> out;
  out.push_back(std::make_unique<SaveCommand>());
  out.push_back(std::make_unique<RestCommand>());
  return out;
}

}  // namespace c2d
