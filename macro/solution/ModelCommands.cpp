// The solution commands that change the model during a run: HINGe2joint
// (hinges become joints), REMOve (members taken out).
#include "macro/run/ProblemRun.h"
#include "macro/solution/SolutionCommandKit.h"

namespace c2d {

namespace {

using namespace batchspec;

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

}  // namespace

std::vector<std::unique_ptr<SolutionCommand>> modelCommands() {
  std::vector<std::unique_ptr<SolutionCommand>> out;
  out.push_back(std::make_unique<HingeToJointCommand>());
  out.push_back(std::make_unique<RemoveCommand>());
  return out;
}

}  // namespace c2d
