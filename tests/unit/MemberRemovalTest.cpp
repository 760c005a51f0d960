// Members removed during a run (solvers/MemberRemoval, BLASt and REMOve): the
// GSA column removal of a two-bay frame against the closed form of the released
// single-degree-of-freedom system (td = 0 and td > 0, a blast time off the step
// grid), the static removal against the frame without the column, the energy
// balance through every removal, nodes leaving the model, and the deck errors.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

using testing::DeckTempDir;
using testing::readCsv;
using testing::runDeckText;

// A two-bay frame (bays L = 4, storey H = 3, clamped bases 1-3), columns 1
// (node 1-4) and 2 (3-12), beams 3-10 (nodes 4..12 along the top, node 8 above
// the middle base), massless; the middle column, when present, is element 11
// (2-8). Node 8 carries the weight W and the lumped mass m: the released
// system is one degree of freedom, the vertical motion of node 8 (the other
// dofs are massless, and by symmetry node 8 does not rotate or sway).
std::string frame(const std::string& extra, const std::string& batch, const std::string& tplot) {
  return "PARAmeter\n  L = 4\n  H = 3\n  m = 10\n  W = 100\n\n"
         "FEAP * * two-bay frame\n  0 0 0 2 3 2\n\n"
         "COORdinates\n  1 0 0 0\n  2 0 L 0\n  3 0 2*L 0\n  4 1 0 H\n  12 0 2*L H\n\n"
         "ELEMents\n  1 0 1 1 4\n  2 0 1 3 12\n  3 1 1 4 5\n  10 0 1 11 12\n\n"
         "MATErial,1\n  FRAMe\n    RESUltant STIFfness 1e7 1e7 1e4\n\n"
         "BOUNdary\n  1 0 1 1 1\n  2 0 1 1 1\n  3 0 1 1 1\n\n"
         "FORCe\n  8 0 0 -W 0\n\n"
         "MASS\n  8 0 m m 0\n\n" +
         extra + "END\nBATCh\n" + batch + "END\n" + tplot + "\nSTOP\n";
}

const std::string kColumn = "ELEMents\n  11 0 1 2 8\n\n";

// Static solution: the vertical stiffness k of node 8 without the column, and
// the column's force N and node 8's deflection v0 with it.
struct Statics {
  double k = 0, N = 0, v0 = 0;
};

Statics statics(const DeckTempDir& dir) {
  Statics s;
  const std::string batch = "  TPLOt\n  DT,,1\n  TIME\n  LOOP,,3\n    TANG,,1\n  NEXT\n";
  // Without the column node 2 is used by no element (a warning).
  auto r = runDeckText(dir, "open.inp", frame("", batch, "disp,8,2\n"));
  EXPECT_EQ(r.outcome.exitCode, 0) << r.console;
  s.k = 100 / -readCsv(r.out / "open_tplot.csv").column("disp_8_2").back();
  r = runDeckText(dir, "closed.inp", frame(kColumn, batch, "disp,8,2\nreac,2,2\n"));
  EXPECT_EQ(r.outcome.exitCode, 0) << r.console;
  const auto csv = readCsv(r.out / "closed_tplot.csv");
  s.v0 = csv.column("disp_8_2").back();
  s.N = std::abs(csv.column("reac_2_2").back());
  return s;
}

// Displacement of the released SDOF m u'' + k u = N g(t), g rising from 0 to 1
// linearly over td (a step for td = 0), from rest at t = 0.
double released(double N, double k, double omega, double td, double t) {
  if (t <= 0) return 0;
  if (td <= 0) return N / k * (1 - std::cos(omega * t));
  const double a = omega * td;
  if (t <= td) return N / k * (t / td - std::sin(omega * t) / a);
  return N / k * (1 - (std::sin(omega * t) - std::sin(omega * (t - td))) / a);
}

struct Removal {
  std::string scheme;  // DYNAmic option
  double tb = 0, td = 0, h = 0;
  int steps = 0;
};

void expectReleasedSdof(const Removal& c, const std::string& name) {
  DeckTempDir dir;
  const Statics s = statics(dir);
  ASSERT_GT(s.k, 0);
  ASSERT_GT(s.N, 0.5 * 100);  // the stiff column carries most of the weight
  const double m = 10;
  // The trapezoidal rule (the mid-point scheme and average-acceleration
  // Newmark on a linear system) runs at the frequency tan(w_h h/2) = w h/2.
  const double omega = std::sqrt(s.k / m);
  const double omegaH = 2 / c.h * std::atan(omega * c.h / 2);
  const std::string blast = "BLASt\n  " + std::to_string(c.tb) + " 11 0 0 " + std::to_string(c.td) + "\n\n";
  const std::string batch = "  DT,," + std::to_string(c.h) +
                            "\n  TIME\n  LOOP,,3\n    TANG,,1\n  NEXT\n"
                            "  DYNAmic," + c.scheme + "\n  TPLOt\n  LOOP,," + std::to_string(c.steps) +
                            "\n    TIME\n    LOOP,,10\n      TANG,,1\n    NEXT\n  NEXT\n";
  const auto r = runDeckText(dir, name + ".inp", frame(kColumn + blast, batch, "disp,8,2\nener\n"));
  ASSERT_EQ(r.outcome.exitCode, 0) << r.console;
  EXPECT_NE(r.log.find("blast  at t = "), std::string::npos) << r.log;
  EXPECT_NE(r.log.find("element 11 removed"), std::string::npos) << r.log;
  EXPECT_NE(r.log.find("node 2 leaves the model"), std::string::npos) << r.log;
  const auto csv = readCsv(r.out / (name + "_tplot.csv"));
  const auto t = csv.column("time"), v = csv.column("disp_8_2"), balance = csv.column("balance");
  const auto kinetic = csv.column("kinetic");
  ASSERT_GT(t.size(), 100u);
  // A step ends exactly at the blast time (the sub-step's row is in the plot).
  bool landed = false;
  double peak = 0, worst = 0, peakEnergy = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    landed = landed || std::abs(t[i] - c.tb) < 1e-12;
    const double expected = s.v0 - released(s.N, s.k, omegaH, c.td, t[i] - c.tb);
    peak = std::max(peak, std::abs(expected - s.v0));
    worst = std::max(worst, std::abs(v[i] - expected));
    peakEnergy = std::max(peakEnergy, kinetic[i]);
  }
  EXPECT_TRUE(landed) << "no step ends at the blast time " << c.tb;
  // The dynamic amplification: 2 for a sudden removal, less over td.
  EXPECT_NEAR(peak, (c.td > 0 ? 1.0 : 2.0) * s.N / s.k, (c.td > 0 ? 1.0 : 1e-3) * s.N / s.k);
  EXPECT_LT(worst, 2e-3 * peak) << "largest difference from the released SDOF";
  // The energy balance stays closed through the removal and the release.
  for (double b : balance) EXPECT_NEAR(b, balance.front(), 1e-9 * peakEnergy);
}

TEST(MemberRemoval, SuddenColumnLossIsTheReleasedSdof) {
  // tb off the step grid: the step is split there.
  expectReleasedSdof({"ENERgy,0,0", 0.0035, 0, 0.001, 800}, "sudden");
}

TEST(MemberRemoval, ColumnForcesReleasedOverTdAreTheRampedSdof) {
  // td = a fifth of the period T = 0.31 s, Newmark (average acceleration).
  expectReleasedSdof({"NEWMark,0.25,0.5", 0.002, 0.0625, 0.001, 800}, "ramped");
}

TEST(MemberRemoval, StaticRemovalGivesTheFrameWithoutTheColumn) {
  DeckTempDir dir;
  const Statics s = statics(dir);
  // REMOve in statics: the next static step is the frame without the column
  // under the same load, v = W / k; STRE reports the element as removed.
  const std::string batch =
      "  TPLOt\n  DT,,1\n  TIME\n  LOOP,,3\n    TANG,,1\n  NEXT\n"
      "  REMOve,ELEMents,11\n  STRE,,11\n  TIME\n  LOOP,,3\n    TANG,,1\n  NEXT\n";
  const auto r = runDeckText(dir, "removed.inp", frame(kColumn, batch, "disp,8,2\nener\n"));
  ASSERT_EQ(r.outcome.exitCode, 0) << r.console;
  EXPECT_NE(r.log.find("remove at t = 1.000000e+00: element 11 removed, at once"),
            std::string::npos)
      << r.log;
  EXPECT_NE(r.log.find("     11  removed"), std::string::npos) << r.log;
  const auto csv = readCsv(r.out / "removed_tplot.csv");
  const auto v = csv.column("disp_8_2");
  ASSERT_GE(v.size(), 2u);
  EXPECT_NEAR(v.front(), s.v0, 1e-12);
  EXPECT_NEAR(v.back(), -100 / s.k, 1e-9 * 100 / s.k);
  EXPECT_NE(r.log.find(", 1 removed,"), std::string::npos) << r.log;
}

TEST(MemberRemoval, AfterHingeToJointTheLooseJointIsDissolvedAndThePiecesFall) {
  // A cantilever (4 elements, lumped mass 0.075 t per element end) turned at
  // its tip past Mu under self-weight: a hinge opens in element 4, HINGe2joint
  // makes it a joint at node 4 (slave node 6). Removing elements 1 and 3 leaves
  // element 2 free and element 4 held only by the tip's rotation restraint:
  // the joint is dissolved (element 4 takes node 6 as its own), nodes 1 and 4
  // leave the model, and the two pieces fall: the conserving scheme keeps
  // their vertical momentum exactly -M g (t - 1), M = 0.3 t.
  DeckTempDir dir;
  const std::string deck =
      "FEAP * * cantilever: hinge, joint, removal\n  0 0 0 2 3 2\n\n"
      "BLOCk\n  CARTesian 4 0 1 1 1\n  1 0 0\n  2 2 0\n\n"
      "MATErial,1\n  FRAMe\n    RESUltant STIFfness 3.6e6 1.25e6 77650\n"
      "    CROSs section 0.12 1.6e-3\n    DENSity,,2.5\n    MASS LUMPed\n"
      "    HARDening BILInear 37.9 268 29400 272\n    SOFTening LINEar 274 -18000\n\n"
      "BOUNdary\n  1 0 1 1 1\n  5 0 0 0 1\n\n"
      "DISPlacement\n  5 0 0 0 0.08\n\n"
      "GRAVity,,0,-9.81\n\n"
      "END\nBATCh\n  PROP,,1\n  DT,,0.1\n  LOOP,,10\n    TIME\n    LOOP,,20\n      TANG,,1\n"
      "    NEXT\n  NEXT\n  HINGe2joint\n  REMOve,ELEMents,1,3,2\n  DYNAmic,ENERgy,0,0\n"
      "  DT,,0.01\n  TPLOt\n  LOOP,,50\n    TIME\n    LOOP,,20\n      TANG,,1\n    NEXT\n"
      "  NEXT\nEND\n\nvelo,2,2\nvelo,3,2\nvelo,6,2\nvelo,5,2\nener\n\nSTOP\n";
  const auto r = runDeckText(dir, "pieces.inp", deck);
  ASSERT_EQ(r.outcome.exitCode, 0) << r.outcome.message;
  EXPECT_NE(r.log.find("element 4: joint master 4 slave 6"), std::string::npos) << r.log;
  EXPECT_NE(r.log.find("elements 1, 3 removed, at once; nodes 1, 4 leave the model; 1 joint "
                       "dissolved"),
            std::string::npos)
      << r.log;
  const auto csv = readCsv(r.out / "pieces_tplot.csv");
  const auto t = csv.column("time"), balance = csv.column("balance");
  ASSERT_EQ(t.size(), 50u);
  for (std::size_t i = 0; i < t.size(); ++i) {
    double p = 0;
    for (int n : {2, 3, 6, 5}) p += 0.075 * csv.column("velo_" + std::to_string(n) + "_2")[i];
    EXPECT_NEAR(p, -0.3 * 9.81 * (t[i] - 1), 1e-9) << "t = " << t[i];
    EXPECT_NEAR(balance[i], balance.front(), 1e-10);
  }
}

TEST(MemberRemoval, RestartDuringAReleaseContinuesBitForBit) {
  // Saved while the column's forces are being released (td = 0.05 s from
  // t = 0.002 s, saved at t = 0.03 s): the released forces, the blast plan and
  // the empty element slot are in the restart file; the continued run's rows
  // equal the uninterrupted run's, as text.
  DeckTempDir dir;
  const std::string blast = kColumn + "BLASt\n  0.002 11 0 0 0.05\n\n";
  const std::string start = "  DT,,0.002\n  TIME\n  LOOP,,3\n    TANG,,1\n  NEXT\n"
                            "  DYNAmic,NEWMark,0.25,0.5\n  TPLOt\n";
  auto steps = [](int n) {
    return "  LOOP,," + std::to_string(n) + "\n    TIME\n    LOOP,,10\n      TANG,,1\n    NEXT\n  NEXT\n";
  };
  const std::string tplot = "disp,8,2\nener\n";
  const auto whole = runDeckText(dir, "whole.inp", frame(blast, start + steps(50), tplot));
  ASSERT_EQ(whole.outcome.exitCode, 0) << whole.outcome.message;
  const auto first = runDeckText(dir, "first.inp", frame(blast, start + steps(14) + "  SAVE,mid\n", tplot));
  ASSERT_EQ(first.outcome.exitCode, 0) << first.outcome.message;
  const auto rest = runDeckText(dir, "rest.inp", frame(blast, "  REST,mid\n  TPLOt\n" + steps(36), tplot));
  ASSERT_EQ(rest.outcome.exitCode, 0) << rest.outcome.message;
  auto rows = [](const std::filesystem::path& p) {
    std::ifstream in(p);
    std::vector<std::string> out;
    for (std::string l; std::getline(in, l);) out.push_back(l);
    return out;
  };
  const auto w = rows(whole.out / "whole_tplot.csv"), r = rows(rest.out / "rest_tplot.csv");
  ASSERT_EQ(r.size(), 37u);
  ASSERT_EQ(w.size(), 51u);
  for (std::size_t i = 1; i < r.size(); ++i) EXPECT_EQ(r[i], w[w.size() - r.size() + i]) << "row " << i;
}

TEST(MemberRemoval, ReleaseStartsFromTheForcesTheElementCarried) {
  // A beam element with a floor load (QLOAd) removed in statics with a long
  // release: at the start of the release the rest carries exactly what it
  // carried before (the element's internal forces and its floor load become
  // the released load), so the first step after the removal moves node 8 by
  // one step of the release only, not by the jump of a sudden removal.
  DeckTempDir dir;
  const std::string extra = kColumn + "QLOAd\n  5 5 1 0 -40\n\n";
  auto run = [&](const std::string& name, const std::string& td) {
    const std::string batch =
        "  TPLOt\n  DT,,1\n  TIME\n  LOOP,,3\n    TANG,,1\n  NEXT\n"
        "  REMOve,ELEMents,5,5,1," + td + "\n  DT,,0.001\n  TIME\n  LOOP,,5\n    TANG,,1\n  NEXT\n";
    const auto r = runDeckText(dir, name + ".inp", frame(extra, batch, "disp,8,2\n"));
    EXPECT_EQ(r.outcome.exitCode, 0) << r.outcome.message;
    const auto v = readCsv(r.out / (name + "_tplot.csv")).column("disp_8_2");
    return v.size() >= 2 ? v.back() - v.front() : 1.0;
  };
  const double sudden = run("sudden", "0"), released = run("released", "1");
  EXPECT_GT(std::abs(sudden), 1e-6);
  EXPECT_LT(std::abs(released), 2e-3 * std::abs(sudden));
}

TEST(MemberRemoval, ABlastTheRunNeverReachesIsWarned) {
  // The plan says t = 5, the run ends at t = 1: said in the log and the summary.
  DeckTempDir dir;
  const std::string batch = "  DT,,1\n  TIME\n  LOOP,,3\n    TANG,,1\n  NEXT\n";
  const auto r = runDeckText(dir, "late.inp", frame(kColumn + "BLASt\n  5 11\n\n", batch, ""));
  ASSERT_EQ(r.outcome.exitCode, 0) << r.outcome.message;
  EXPECT_NE(r.log.find("warning: the blast at t = 5.000000e+00 did not happen: the run "
                       "ended at t = 1.000000e+00"),
            std::string::npos)
      << r.log;
  EXPECT_NE(r.log.find("warning: 1 blast of the BLASt plan did not happen"), std::string::npos)
      << r.log;
}

TEST(MemberRemoval, ABlastOfElementsRemovedBeforeIsWarned) {
  // REMOve takes the column at t = 1, the plan blasts it at t = 2: that blast
  // removes nothing (it logged a blast of an empty list, without a warning).
  // Known when the deck is bound: a warning at the BLASt record before any
  // step, naming the REMOve; at t = 2 the log's warning names the record.
  DeckTempDir dir;
  const std::string batch =
      "  DT,,1\n  TIME\n  LOOP,,3\n    TANG,,1\n  NEXT\n"
      "  REMOve,ELEMents,11\n  LOOP,,2\n    TIME\n    LOOP,,3\n"
      "      TANG,,1\n    NEXT\n  NEXT\n";
  const auto r = runDeckText(dir, "again.inp", frame(kColumn + "BLASt\n  2 11\n\n", batch, ""));
  ASSERT_EQ(r.outcome.exitCode, 0) << r.outcome.message;
  ASSERT_EQ(r.outcome.warnings.size(), 1u);
  const DeckWarning& w = r.outcome.warnings[0];
  EXPECT_EQ(w.loc.str(), (dir.path() / "again.inp").string() + ":42:3");
  EXPECT_NE(w.message.find("BLASt of element 11, which the REMOve of " +
                           (dir.path() / "again.inp").string() + ":51:3 removes too"),
            std::string::npos)
      << w.message;
  EXPECT_NE(r.log.find("warning: the blast at t = 2.000000e+00 (BLASt record " +
                       (dir.path() / "again.inp").string() +
                       ":42:3) removes nothing: its element 11 was removed before by REMOve"),
            std::string::npos)
      << r.log;
  EXPECT_NE(r.log.find("warning: 1 blast of the BLASt plan did not happen"), std::string::npos)
      << r.log;
  EXPECT_EQ(r.log.find("blast  at t"), std::string::npos) << r.log;
}

TEST(MemberRemoval, AMeshReentryAfterARemovalKeepsTheEmptySlots) {
  // The column removed, then MESH gives a load again: the removed element's
  // slot stays empty (it was refused as "element 11 is not defined ...
  // element numbers must run from 1 without gaps").
  DeckTempDir dir;
  const std::string batch =
      "  DT,,1\n  TIME\n  LOOP,,3\n    TANG,,1\n  NEXT\n"
      "  REMOve,ELEMents,11\n  MESH\n  TIME\n  LOOP,,3\n    TANG,,1\n"
      "  NEXT\n";
  // The re-entry's records follow the BATCh END (frame's last argument).
  const auto r =
      runDeckText(dir, "reentry.inp", frame(kColumn, batch, "FORCe\n  8 0 0 -2*W 0\n\nEND\n"));
  ASSERT_EQ(r.outcome.exitCode, 0) << r.outcome.message;
  EXPECT_NE(r.log.find("MESH   re-entered"), std::string::npos) << r.log;
}

TEST(MemberRemoval, RemovingEveryElementIsAnAnalysisError) {
  // Nothing would be left to compute (the linear solver's symbolic analysis
  // of an empty matrix failed instead).
  DeckTempDir dir;
  const std::string solved = "  DT,,1\n  TIME\n  LOOP,,3\n    TANG,,1\n  NEXT\n";
  auto r = runDeckText(dir, "all.inp", frame(kColumn, solved + "  REMOve,ELEMents,1,11\n", ""));
  EXPECT_EQ(r.outcome.exitCode, 2);
  EXPECT_NE(r.outcome.message.find("no element would be left: every element of the model (11) "
                                   "is in the list"),
            std::string::npos)
      << r.outcome.message;
  // The last elements by a blast, after REMOve took the others.
  const std::string later = solved +
                            "  REMOve,ELEMents,1,10\n  TIME\n  LOOP,,3\n    TANG,,1\n"
                            "  NEXT\n";
  r = runDeckText(dir, "last.inp", frame(kColumn + "BLASt\n  2 11\n\n", later, ""));
  EXPECT_EQ(r.outcome.exitCode, 2);
  EXPECT_NE(r.outcome.message.find("the blast at t = 2.000000e+00: no element would be left: the "
                                   "model's last element is in the list"),
            std::string::npos)
      << r.outcome.message;
}

TEST(MemberRemoval, RemovalInAStepNotSolvedIsAnAnalysisError) {
  // TIME begins a step; REMOve before its Newton loop converged has no state to act on.
  DeckTempDir dir;
  const std::string batch = "  DT,,1\n  TIME\n  REMOve,ELEMents,11\n";
  const auto r = runDeckText(dir, "unsolved.inp", frame(kColumn, batch, ""));
  EXPECT_EQ(r.outcome.exitCode, 2);
  EXPECT_NE(r.outcome.message.find("the current step has not converged"), std::string::npos)
      << r.outcome.message;
}

TEST(MemberRemoval, RemovedTwiceIsAnAnalysisError) {
  DeckTempDir dir;
  const std::string batch =
      "  DT,,1\n  TIME\n  LOOP,,3\n    TANG,,1\n  NEXT\n  REMOve,ELEMents,11\n  REMOve,ELEMents,11\n";
  const auto r = runDeckText(dir, "twice.inp", frame(kColumn, batch, ""));
  EXPECT_EQ(r.outcome.exitCode, 2);
  EXPECT_NE(r.outcome.message.find("element 11 is not in the model (removed before)"),
            std::string::npos)
      << r.outcome.message;
}

TEST(MemberRemoval, BlastDeckErrorsAreLocated) {
  DeckTempDir dir;
  const std::string batch = "  DT,,1\n  TIME\n  TANG,,1\n";
  auto r = runDeckText(dir, "undefined.inp", frame(kColumn + "BLASt\n  1 12\n\n", batch, ""));
  EXPECT_EQ(r.outcome.exitCode, 1);
  EXPECT_NE(r.outcome.message.find("undefined.inp:42:5: error: BLASt: element 12 is not defined"),
            std::string::npos)
      << r.outcome.message;
  r = runDeckText(dir, "twice.inp", frame(kColumn + "BLASt\n  1 11\n  2 11\n\n", batch, ""));
  EXPECT_EQ(r.outcome.exitCode, 1);
  EXPECT_NE(r.outcome.message.find("element 11 is already removed by an earlier record"),
            std::string::npos)
      << r.outcome.message;
  r = runDeckText(dir, "negative.inp", frame(kColumn + "BLASt\n  1 11 0 0 -1\n\n", batch, ""));
  EXPECT_EQ(r.outcome.exitCode, 1);
  EXPECT_NE(r.outcome.message.find("the release time td must be zero or positive"), std::string::npos)
      << r.outcome.message;
  r = runDeckText(dir, "option.inp", frame(kColumn, batch + "  REMOve,NODEs,1\n", ""));
  EXPECT_EQ(r.outcome.exitCode, 1);
  EXPECT_NE(r.outcome.message.find("unknown option 'NODEs' (ELEMents)"), std::string::npos)
      << r.outcome.message;
}

}  // namespace
}  // namespace c2d
