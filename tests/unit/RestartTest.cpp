// Restart files (SAVE / REST): a run restarted from a save repeats the
// uninterrupted run bit for bit, across hinge formation, HINGE2JOINT, MESH
// re-entry and into the dynamic phase; a killed run leaves only .part files.
// Bad files: RestartFileTest.
#include <gtest/gtest.h>

#include <algorithm>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>

#include "core/io/Checkpoint.h"
#include "core/Hinge.h"
#include "elements/JointedElement.h"
#include "elements/Joints.h"
#include "elements/ModelCheckpoint.h"
#include "solvers/RestartFile.h"
#include "tests/unit/OutputTestSupport.h"
#include "tests/unit/RestartTestSupport.h"
#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

using testing::DeckResult;
using testing::DeckTempDir;
using testing::expectRan;
using testing::kLoads;
using testing::kPortal;
using testing::kStart;
using testing::kTplot;
using testing::lines;
using testing::newtonLoop;
using testing::readText;
using testing::runDeckText;

const char* kCollapseMesh = "CONTact\n  GROUnd,,0,1e5\n\nGRAVity,,0,-9.81\n\nEND\n";

const std::string kFailureEnd = newtonLoop("TIME,,2", 1000) + "  STRE,HINGe\n";
// HINGE2JOINT, ground and gravity by MESH re-entry, ten steps of the mid-point scheme.
const std::string kCollapseStart =
    "  HINGe2joint\n  MESH\n  DYNAmic,ENERgy,0.1,0.1\n  DT,,0.02\n" + newtonLoop("TIME", 10);
const std::string kCollapseEnd = newtonLoop("TIME", 10);

// A model and an analysis read back from a restart file.
struct Loaded {
  Model model;
  std::unique_ptr<Analysis> analysis;
  explicit Loaded(const std::filesystem::path& file) {
    analysis = std::make_unique<Analysis>(model);
    loadRestart(file, model, *analysis);
  }
};

bool sameBits(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return a.size() == b.size() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}
bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// The final states of two runs, bit for bit: state vectors, time, load factors,
// element section forces and hinges, energies.
void expectSameState(const std::filesystem::path& a, const std::filesystem::path& b) {
  Loaded x(a), y(b);
  const State &s = x.analysis->state(), &t = y.analysis->state();
  EXPECT_EQ(s.step, t.step);
  EXPECT_TRUE(sameBits(s.u, t.u));
  EXPECT_TRUE(sameBits(s.v, t.v));
  EXPECT_TRUE(sameBits(s.a, t.a));
  EXPECT_TRUE(sameBits(s.un, t.un));
  for (auto [p, q] : {std::pair{s.t, t.t}, {s.dt, t.dt}, {s.prop, t.prop}, {s.arcLambda, t.arcLambda}})
    EXPECT_TRUE(sameBits(p, q));
  ASSERT_EQ(x.model.numNodes(), y.model.numNodes());
  ASSERT_EQ(x.model.numElements(), y.model.numElements());
  for (int e = 0; e < x.model.numElements(); ++e) {
    ASSERT_EQ(x.model.hasElement(e), y.model.hasElement(e)) << "element " << e + 1;
    if (!x.model.hasElement(e)) continue;
    const SectionForces f = x.model.element(e).sectionForces(), g = y.model.element(e).sectionForces();
    EXPECT_TRUE(sameBits(f.N, g.N) && sameBits(f.V, g.V) && sameBits(f.M, g.M)) << "element " << e + 1;
    EXPECT_EQ(x.model.element(e).typeName(), y.model.element(e).typeName());
    const auto* h1 = dynamic_cast<const HingeCarrier*>(&x.model.element(e));
    const auto* h2 = dynamic_cast<const HingeCarrier*>(&y.model.element(e));
    ASSERT_EQ(h1 == nullptr, h2 == nullptr);
    if (h1) {
      EXPECT_EQ(h1->hinge().active, h2->hinge().active);
      EXPECT_TRUE(sameBits(h1->hinge().jump, h2->hinge().jump));
    }
  }
  const Energy e1 = x.analysis->energy(), e2 = y.analysis->energy();
  EXPECT_TRUE(sameBits(e1.external, e2.external));
}

// Rows of the restarted run's TPLOt equal the last rows of the uninterrupted
// one, as text; the two together make up the whole history.
void expectSameTail(const std::string& whole, const std::string& first, const std::string& rest) {
  const auto w = lines(whole), f = lines(first), r = lines(rest);
  ASSERT_GT(r.size(), 2u);
  ASSERT_EQ(w.size(), f.size() + r.size() - 1) << "header + rows before + rows after the save";
  EXPECT_EQ(w.front(), r.front());
  for (std::size_t i = 1; i < r.size(); ++i) EXPECT_EQ(r[i], w[w.size() - r.size() + i]) << "row " << i;
  for (std::size_t i = 1; i < f.size(); ++i) EXPECT_EQ(f[i], w[i]) << "row " << i;
}

TEST(Restart, FailurePhaseContinuesBitForBit) {
  DeckTempDir dir;
  const std::string data = std::string(kLoads) + kTplot;
  const DeckResult whole = runDeckText(dir, "whole.inp", kPortal + kStart + kFailureEnd + "  SAVE,whole_end\nEND\n" + data);
  expectRan(whole);
  const DeckResult first = runDeckText(dir, "first.inp", kPortal + kStart + "  SAVE,mid\nEND\n" + data);
  expectRan(first);
  const DeckResult rest = runDeckText(dir, "rest.inp", kPortal + std::string("  REST,mid\n  TPLOt\n") +
                                                           kFailureEnd + "  SAVE,rest_end\nEND\n" + kTplot);
  expectRan(rest);
  // Hinges 3 and 4 formed before the save, 1 and 6 after it, in the restarted run.
  EXPECT_NE(first.log.find("formed in element 3"), std::string::npos);
  EXPECT_EQ(first.log.find("formed in element 1 "), std::string::npos);
  EXPECT_NE(rest.log.find("formed in element 1 "), std::string::npos);
  EXPECT_NE(rest.log.find("  REST   "), std::string::npos);
  expectSameTail(readText(whole.out / "whole_tplot.csv"), readText(first.out / "first_tplot.csv"),
                 readText(rest.out / "rest_tplot.csv"));
  expectSameState(whole.out / "whole_end.rst", rest.out / "rest_end.rst");
  // The hinge table (steps, jumps, moments) of the restarted run is the uninterrupted one's.
  const auto table = [](const std::string& log) {
    const std::size_t at = log.rfind("S o f t e n i n g");
    return at == std::string::npos ? std::string() : log.substr(at, log.find("hinges", at) - at);
  };
  EXPECT_NE(table(rest.log).find("   43  "), std::string::npos) << table(rest.log);
  EXPECT_EQ(table(whole.log), table(rest.log));
}

TEST(Restart, AcrossHingeToJointIntoTheCollapsePhase) {
  DeckTempDir dir;
  const std::string data = std::string(kLoads) + kTplot + kCollapseMesh;
  const std::string head = kPortal + kStart + kFailureEnd + kCollapseStart;
  const DeckResult whole = runDeckText(dir, "whole.inp", head + kCollapseEnd + "  SAVE,whole_end\nEND\n" + data);
  expectRan(whole);
  // A SAVE in the middle does not change the run.
  const DeckResult saving = runDeckText(dir, "saving.inp", head + "  SAVE\n" + kCollapseEnd + "  SAVE,saving_end\nEND\n" + data);
  expectRan(saving);
  EXPECT_EQ(readText(whole.out / "whole_tplot.csv"), readText(saving.out / "saving_tplot.csv"));
  expectSameState(whole.out / "whole_end.rst", saving.out / "saving_end.rst");

  const DeckResult first = runDeckText(dir, "first.inp", head + "  SAVE,mid\nEND\n" + data);
  expectRan(first);
  const DeckResult rest = runDeckText(dir, "rest.inp", kPortal + std::string("  REST,mid\n  TPLOt\n") +
                                                           kCollapseEnd + "  SAVE,rest_end\nEND\n" + kTplot);
  expectRan(rest);
  expectSameTail(readText(whole.out / "whole_tplot.csv"), readText(first.out / "first_tplot.csv"),
                 readText(rest.out / "rest_tplot.csv"));
  expectSameState(whole.out / "whole_end.rst", rest.out / "rest_end.rst");

  // The saved model is the collapse-phase one: slave nodes, joints, jointed
  // Reissner elements with their relative rotations, ground and gravity.
  Loaded mid(first.out / "mid.rst");
  EXPECT_EQ(mid.model.numNodes(), 11);
  EXPECT_EQ(mid.model.joints().size(), 4u);
  EXPECT_TRUE(mid.model.ground().has_value());
  EXPECT_EQ(mid.model.gravity().y(), -9.81);
  EXPECT_EQ(mid.analysis->integrator().kind, TimeIntegrator::Kind::MidPoint);
  const auto jointed = jointedElements(mid.model);
  ASSERT_EQ(jointed.size(), 4u);
  for (const JointedElement* j : jointed) {
    EXPECT_EQ(j->inner().typeName(), "frame-reissner");
    EXPECT_NE(j->committedRelativeRotation(), 0.0);
  }
}

// A bar dropped across a fixed beam (member contact) beside a beam sliding on
// the ground with friction on a crushing ground (e = 0.5): saved in the middle
// of the impact, with the friction springs' stretches and the loading points
// in the state.
const char* kContact = R"(PARAmeter
  h = sqrt(3*1e-3/1.25) + sqrt(3*1e-3/0.5)

FEAP * * member contact and friction
  0 0 0 2 3 2

COORdinates
  1 1 0   0
  3 0 4   0
  4 0 0.6 h+0.05
  5 0 1.4 h+0.05
  6 0 6   -9.81/2e5
  7 0 7   -9.81/2e5

ELEMents
  1 1 2 1 2
  2 0 2 2 3
  3 0 1 4 5
  4 0 1 6 7

MATErial,1
  FRAMe
    RESUltant STIFfness 1e7 1e7 1e5
    CROSs section 1.25 1e-3
    DENSity,,1
    FINIte

MATErial,2
  FRAMe
    RESUltant STIFfness 1e6 1e6 1e3
    CROSs section 0.5 1e-3
    DENSity,,1
    FINIte

BOUNdary
  1 0 1 1 1
  2 0 1 1 1
  3 0 1 1 1

CONTact
  GROUnd,,0,1e5,,0.2,0.5
  MEMBers,,2e4,,,0.3,0.5

GRAVity,,2.943,-9.81

END
BATCh
  DYNAmic,ENERgy,0,0
  TOL,,1e-20
  DT,,1e-3
  TPLOt
)";

TEST(Restart, MemberContactAndFrictionContinueBitForBit) {
  DeckTempDir dir;
  const std::string data = "disp,4,2\ndisp,6,1\nener\n\nSTOP\n";
  const DeckResult whole = runDeckText(
      dir, "whole.inp", kContact + newtonLoop("TIME", 140) + "  SAVE,whole_end\nEND\n" + data);
  expectRan(whole);
  const DeckResult first =
      runDeckText(dir, "first.inp", kContact + newtonLoop("TIME", 106) + "  SAVE,mid\nEND\n" + data);
  expectRan(first);
  const DeckResult rest = runDeckText(
      dir, "rest.inp",
      std::string(kContact).substr(0, std::string(kContact).find("  DYNA")) + "  REST,mid\n  TPLOt\n" +
          newtonLoop("TIME", 34) + "  SAVE,rest_end\nEND\n" + data);
  expectRan(rest);
  // The save falls inside the impact: the bar is in contact with the beam.
  const Loaded mid(first.out / "mid.rst");
  EXPECT_GT(mid.analysis->energy().contact, 1e-3);
  EXPECT_GT(mid.analysis->state().crush.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_GT(mid.analysis->state().stretch.cwiseAbs().maxCoeff(), 0.0);
  // The member contact pairs' memory: loading points and friction stretches.
  const std::vector<PairMemory>& pairs = mid.analysis->state().pairs;
  EXPECT_TRUE(std::any_of(pairs.begin(), pairs.end(), [](const PairMemory& p) { return p.q > 0; }));
  EXPECT_TRUE(
      std::any_of(pairs.begin(), pairs.end(), [](const PairMemory& p) { return p.stretch != 0; }));
  expectSameTail(readText(whole.out / "whole_tplot.csv"), readText(first.out / "first_tplot.csv"),
                 readText(rest.out / "rest_tplot.csv"));
  expectSameState(whole.out / "whole_end.rst", rest.out / "rest_end.rst");
}

// The same under DYNAmic,ENERgy's decay, saved while a ground node's impact
// owes what the scheme took from it (State::owed): the restart continues bit
// for bit.
TEST(Restart, GroundImpactOwedContinuesBitForBit) {
  const int saveStep = 60;  // inside the bar's first ground impact
  DeckTempDir dir;
  std::string deck = kContact;
  deck.replace(deck.find("DYNAmic,ENERgy,0,0"), 18, "DYNAmic,ENERgy,0.1,0.1");
  const std::string data = "disp,4,2\ndisp,6,1\nener\n\nSTOP\n";
  const DeckResult whole =
      runDeckText(dir, "whole.inp", deck + newtonLoop("TIME", 140) + "  SAVE,whole_end\nEND\n" + data);
  expectRan(whole);
  const DeckResult first =
      runDeckText(dir, "first.inp", deck + newtonLoop("TIME", saveStep) + "  SAVE,mid\nEND\n" + data);
  expectRan(first);
  const DeckResult rest = runDeckText(
      dir, "rest.inp",
      deck.substr(0, deck.find("  DYNA")) + "  REST,mid\n  TPLOt\n" +
          newtonLoop("TIME", 140 - saveStep) + "  SAVE,rest_end\nEND\n" + data);
  expectRan(rest);
  const Loaded mid(first.out / "mid.rst");
  EXPECT_GT(mid.analysis->state().owed.maxCoeff(), 0.0);
  expectSameTail(readText(whole.out / "whole_tplot.csv"), readText(first.out / "first_tplot.csv"),
                 readText(rest.out / "rest_tplot.csv"));
  expectSameState(whole.out / "whole_end.rst", rest.out / "rest_end.rst");
}

// An RC column (SECTion, FINIte) under axial force pushed at its tip: the base
// hinge opens as a joint carrying the softening law that follows N. Saved
// while that hinge softens, the restarted run continues bit for bit (the
// section, the end hinge's joint and law, the axial history).
const char* kRcColumn = R"(FEAP * * RC column: end hinge, softening under N
  0 0 0 2 3 2

COORdinates
  1 1 0 0
  5 0 0 3

ELEMents
  1 1 1 1 2
  4 0 1 4 5

MATErial,1 column
  FRAMe
    SECTion RECTangular 0.5 0.5 30e3 500e3
    REBAr 0.05 1.2566e-3 0.45 1.2566e-3
    STIRrups 1e-4 0.2
    DENSity,,2.5
    FINIte

BOUNdary
  1 0 1 1 1
  5 0 1 0 0

FORCe
  5 0 0 -1500 0

DISPlacement
  5 0 1 0 0

FPROportional
  5 0 2 1 1

END
BATCh
)";

// deck: kRcColumn or a variant of it.
void rcColumnContinuesBitForBit(const std::string& deck) {
  DeckTempDir dir;
  const std::string start =
      "  PROP,,1\n  PROP,,2\n  TPLOt\n  DT,,1\n" + newtonLoop("TIME", 1) + "  DT,,0.002\n";
  const std::string loads = "2\n  0 1 1e6 1\n\n2\n  0 0 1 0 1e6 1e6-1\n\n";
  const std::string data = loads + "reac,1,3\ndisp,5,1\nstre,1,1\n\nSTOP\n";
  const std::string restData = "reac,1,3\ndisp,5,1\nstre,1,1\n\nSTOP\n";
  const DeckResult whole =
      runDeckText(dir, "whole.inp",
                  deck + start + newtonLoop("TIME", 30) + "  SAVE,whole_end\nEND\n" + data);
  expectRan(whole);
  const DeckResult first = runDeckText(
      dir, "first.inp", deck + start + newtonLoop("TIME", 15) + "  SAVE,mid\nEND\n" + data);
  expectRan(first);
  const DeckResult rest =
      runDeckText(dir, "rest.inp",
                  deck + "  REST,mid\n  TPLOt\n" + newtonLoop("TIME", 15) +
                      "  SAVE,rest_end\nEND\n" + restData);
  expectRan(rest);
  // The save falls while the base hinge softens: its joint is in the model.
  const Loaded mid(first.out / "mid.rst");
  EXPECT_GT(mid.model.numNodes(), 5);
  // The stirrups with the section: the shortest piece derived again.
  ASSERT_TRUE(mid.model.material(1)->section->stirrups.has_value());
  EXPECT_EQ(mid.model.material(1)->section->stirrups->spacing, 0.2);
  EXPECT_GT(mid.model.material(1)->softening->pieceLength, 1.0);
  EXPECT_NE(first.log.find("hinge  opened"), std::string::npos);
  expectSameTail(readText(whole.out / "whole_tplot.csv"), readText(first.out / "first_tplot.csv"),
                 readText(rest.out / "rest_tplot.csv"));
  expectSameState(whole.out / "whole_end.rst", rest.out / "rest_end.rst");
}

TEST(Restart, RcMemberWithAnOpenEndHingeContinuesBitForBit) { rcColumnContinuesBitForBit(kRcColumn); }

// The column with a rigid zone of 0.3 m at its base: its hinge's joint is at
// the face (elements/JointedElement.h), the shift's history in the file.
TEST(Restart, RcMemberWithAHingeAtAZonesFaceContinuesBitForBit) {
  std::string deck = kRcColumn;
  const std::string at = "BOUNdary\n";
  deck.insert(deck.find(at), "RIGId\n  1 0.3 0\n\n");
  rcColumnContinuesBitForBit(deck);
  DeckTempDir dir;
  const DeckResult run = runDeckText(
      dir, "zone.inp",
      deck + "  PROP,,1\n  PROP,,2\n  DT,,1\n" + newtonLoop("TIME", 1) + "  DT,,0.002\n" +
          newtonLoop("TIME", 15) + "  SAVE,mid\nEND\n2\n  0 1 1e6 1\n\n2\n  0 0 1 0 1e6 1e6-1\n\nSTOP\n");
  expectRan(run);
  const Loaded mid(run.out / "mid.rst");
  const std::vector<const JointedElement*> joints = jointedElements(mid.model);
  ASSERT_EQ(joints.size(), 1u);
  EXPECT_TRUE(joints.front()->hasArm());
  EXPECT_NE(joints.front()->committedRelativeRotation(), 0.0);
}

// A bar dropped on a crushing ground, run until at rest (TIME,REST).
const char* kAtRest = R"(FEAP * * bar dropped on a crushing ground, run until at rest
  0 0 0 2 3 2

BLOCk
  CARTesian 4 0 1 1 1
  1 0 0.05
  2 2 0.05

MATErial,1
  FRAMe
    RESUltant STIFfness 1e7 1e7 1e5
    CROSs section 1 1e-3
    DENSity,,1
    FINIte

CONTact
  GROUnd,,0,1e4,1,,0.3

GRAVity,,0,-9.81

END
BATCh
  DYNAmic,ENERgy,0.1,0.1
  DT,,1e-3
  TPLOt
)";

TEST(Restart, TimeRestEndsWhereTheUninterruptedRunEnds) {
  // The kinetic energy's peak and the time it was last above the watched
  // ratio travel in the restart file: saved after the impact, the restarted
  // run comes to rest at the same step as the uninterrupted one.
  DeckTempDir dir;
  const std::string data = "disp,3,2\nener\n\nSTOP\n";
  const std::string rest = "TIME,REST,10,1e-6,0.1";
  const DeckResult whole = runDeckText(
      dir, "whole.inp", kAtRest + newtonLoop(rest, 100000) + "  SAVE,whole_end\nEND\n" + data);
  expectRan(whole);
  const DeckResult first =
      runDeckText(dir, "first.inp", kAtRest + newtonLoop(rest, 150) + "  SAVE,mid\nEND\n" + data);
  expectRan(first);
  const DeckResult second = runDeckText(
      dir, "second.inp",
      std::string(kAtRest).substr(0, std::string(kAtRest).find("  DYNA")) +
          "  REST,mid\n  TPLOt\n" + newtonLoop(rest, 100000) + "  SAVE,second_end\nEND\n" + data);
  expectRan(second);
  EXPECT_NE(whole.log.find("at rest at t = "), std::string::npos);
  expectSameTail(readText(whole.out / "whole_tplot.csv"), readText(first.out / "first_tplot.csv"),
                 readText(second.out / "second_tplot.csv"));
  expectSameState(whole.out / "whole_end.rst", second.out / "second_end.rst");
  // The debris figures of the run, the peak ground force and the deepest node
  // of the impact before the save included.
  const std::string debris = readText(whole.out / "whole_debris.csv");
  EXPECT_NE(debris.find("peak_time,deepest,deepest_time"), std::string::npos) << debris;
  EXPECT_EQ(debris, readText(second.out / "second_debris.csv"));
}

// The collapse2d binary beside the test binary's directory, if built.
std::filesystem::path collapse2dBinary() {
  std::error_code ec;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  const auto exe = self.parent_path().parent_path() / "collapse2d";
  return std::filesystem::exists(exe) ? exe : std::filesystem::path{};
}

TEST(Restart, KilledRunLeavesOnlyPartFiles) {
  DeckTempDir dir;
  // A pendulum swinging for a very long time; TPLOt every step, SAVE at the end.
  const std::string deck = dir.write("long.inp", R"(FEAP * * pendulum
  0 0 0 2 3 2

BLOCk
  CARTesian 4 0 1 1 1
  1 0 0
  2 1 0

MATErial,1
  FRAMe
    RESUltant STIFfness 1e6 1e6 1e4
    CROSs section 1 1e-4
    DENSity,,1
    FINIte

BOUNdary
  1 0 1 1 0

GRAVity,,0,-9.81

END
BATCh
  DYNAmic,ENERgy,0,0
  DT,,0.01
  TPLOt
  LOOP,,100000000
    TIME
    LOOP,,20
      TANG,,1
    NEXT
  NEXT
  SAVE
END
disp,5,2
ener

)");
  const std::filesystem::path out = dir.path() / "out";
  const std::filesystem::path exe = collapse2dBinary();
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    if (!exe.empty()) {
      execl(exe.c_str(), exe.c_str(), "-q", "-o", out.c_str(), deck.c_str(), static_cast<char*>(nullptr));
      _exit(127);
    }
    DeckOptions o;
    o.outDir = out;
    o.quiet = true;
    const SolutionCommands commands;
    std::ostringstream console;
    runDeck(deck, o, commands, console);
    _exit(0);
  }
  // Kill once the run is well under way (its time history has started).
  const auto part = [&] { return testing::partFileOf(out / "long_tplot.csv"); };
  for (int i = 0; i < 500 && part().empty(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run ended before it was killed";
  EXPECT_FALSE(part().empty());
  EXPECT_FALSE(std::filesystem::exists(out / "long_tplot.csv"));
  EXPECT_FALSE(std::filesystem::exists(out / "long.rst"));
  for (const auto& f : std::filesystem::directory_iterator(out)) {
    const std::string name = f.path().filename().string();
    if (name.ends_with(".csv") || name.ends_with(".rst"))
      ADD_FAILURE() << "complete-looking output " << name << " after a killed run";
  }
}

}  // namespace
}  // namespace c2d
