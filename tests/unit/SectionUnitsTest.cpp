// Values of an RC section or a shortest piece that look like another unit are
// located warnings naming the likely unit (macro/mesh/SectionUnits), one
// per rule, and plausible values give none.
#include <gtest/gtest.h>

#include <string>

#include "macro/mesh/SectionUnits.h"
#include "macro/deck/DeckParser.h"
#include "macro/mesh/ParseDeck.h"
#include "macro/mesh/MeshBinder.h"
#include "macro/deck/Warnings.h"
#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

// A column of 3 m in two elements (lines 1-11), material set 1 at line 12, its
// SECTion at line 14 (b h fc fy: columns 22, 26, 30, 35), REBAr at 15, then
// `more` (line 16 on).
std::string columnDeck(const std::string& section, const std::string& rebar,
                       const std::string& more) {
  return "FEAP * * x\n0 0 0 2 3 2\nCOOR\n 1 0 0 0\n 2 0 0 1.5\n 3 0 0 3\n\n"
         "ELEM\n 1 0 1 1 2\n 2 0 1 2 3\n\n"
         "MATE,1\n FRAMe\n SECTion RECTangular " +
         section + "\n REBAr " + rebar + "\n" + more + "\n\nEND\nSTOP\n";
}
const std::string kSection = "0.3 0.5 30e3 500e3";
const std::string kBars = "0.04 4e-4 0.45 9.42e-4";

Warnings warningsOf(const std::string& text) {
  const Deck d = parseDeckText(text, "t.inp");
  Parameters params;
  Warnings w;
  MeshFacts facts;
  facts.warnings = &w;
  buildModel(std::get<Problem>(d.items.at(0)), params, nullptr, &facts);
  return w;
}

// Exactly one warning, at line:col, unit-flagged, its message holding `text`.
void expectOne(const std::string& deck, int line, int col, const std::string& text) {
  const Warnings w = warningsOf(deck);
  ASSERT_EQ(w.list().size(), 1u) << (w.empty() ? "none" : w.list()[0].str());
  const DeckWarning& x = w.list()[0];
  EXPECT_EQ(x.loc.str(), "t.inp:" + std::to_string(line) + ":" + std::to_string(col)) << x.str();
  EXPECT_NE(x.message.find(text), std::string::npos) << x.str();
  EXPECT_TRUE(x.unit);
  EXPECT_EQ(w.unitLocations(), x.loc.str());
}

TEST(SectionUnits, PlausibleValuesWarnNothing) {
  EXPECT_TRUE(warningsOf(columnDeck(kSection, kBars, " STIRrups 1e-4 0.2")).empty());
  EXPECT_TRUE(warningsOf(columnDeck("0.3 0.5 30e3 500e3 200e6 540e3 0.05", kBars,
                                    " STIRrups,,1e-4,0.5,400e3"))
                  .empty());
}

TEST(SectionUnits, StressesInAnotherUnit) {
  // fc = 4000 psi is 27.6 MPa; read as kN/m^2 it is 4 MPa (refused below 1 MPa).
  expectOne(columnDeck("0.3 0.5 4000 500e3", kBars, ""), 14, 30,
            "fc = 4000 is not a concrete strength in the deck's kN/m^2 (5000-150e3, i.e. 5-150 "
            "MPa): psi? 4000 psi is 27.58e3 kN/m^2");
  expectOne(columnDeck("0.3 0.5 30e3 500", kBars, ""), 14, 35,
            "fy = 500 is not a bar's yield stress in the deck's kN/m^2 (100e3-2.5e6, i.e. "
            "100-2500 MPa): MPa? 500 MPa is 500e3 kN/m^2");
  expectOne(columnDeck("0.3 0.5 30e3 500e3 200e9", kBars, ""), 14, 41,
            "Es = 200e9 is not a bar's modulus in the deck's kN/m^2 (100e6-300e6, i.e. "
            "100e3-300e3 MPa): Pa? 200e9 Pa is 200e6 kN/m^2");
  expectOne(columnDeck(kSection, kBars, " STIRrups 1e-4 0.2 400"), 16, 20,
            "fyw = 400 is not a link's yield stress");
}

TEST(SectionUnits, LengthsAndAreasInAnotherUnit) {
  expectOne(columnDeck("300 0.5 30e3 500e3", kBars, ""), 14, 22,
            "the section's size 300 is not in the deck's m (no section is 30 m deep): mm? 300 "
            "mm is 0.3 m");
  // A layer of 0.3 m^2 in a 3 m square (3.4 % of it: below the tenth refused).
  expectOne(columnDeck("3 3 30e3 500e3", "0.1 0.3 2.9 0.01", ""), 15, 12,
            "a bar layer of 0.3 m^2 is more than 0.05 m^2");
  expectOne(
      "FEAP * * x\n0 0 0 2 3 2\nCOOR\n 1 0 0 0\n 2 0 0 5\n\nELEM\n 1 0 1 1 2\n\n"
      "MATE,1\n FRAMe\n SECTion CIRCular 2 30e3 500e3\n REBAr RING 12 6e-3 0.1\n\nEND\n",
      13, 16, "a bar of 6e-3 m^2 is more than 5e-3 m^2");
  // Asw in cm^2: one 1.0 cm^2 pair of legs.
  expectOne(columnDeck(kSection, kBars, " STIRrups 1.0 0.2"), 16, 11,
            "links of Asw/(b s) = 16.67 are more than 0.1 of the section");
  expectOne(columnDeck(kSection, kBars, " STIRrups 1e-4 0.8"), 16, 16,
            "links at s = 0.8 are farther apart than the section is deep (h = 0.5)");
}

TEST(SectionUnits, LengthsAgainstTheMembers) {
  // The link spacing in mm: farther apart than h and longer than the member.
  const Warnings w = warningsOf(columnDeck(kSection, kBars, " STIRrups 1e-4 200"));
  ASSERT_EQ(w.list().size(), 2u);
  EXPECT_EQ(w.list()[1].loc.str(), "t.inp:16:16");
  EXPECT_NE(w.list()[1].message.find("the link spacing s = 200 is longer than the longest member "
                                     "of material set 1 (3 m, its elements in line): mm? 200 mm "
                                     "is 0.2 m"),
            std::string::npos)
      << w.list()[1].str();
  expectOne(columnDeck("0.3 4 30e3 500e3", "0.04 4e-4 3.9 9.42e-4", ""), 14, 26,
            "the section's depth = 4 is longer than the longest member of material set 1 (3 m");
  // A hand-given shortest piece Lb in mm.
  expectOne(
      "FEAP * * x\n0 0 0 2 3 2\nCOOR\n 1 0 0 0\n 2 0 0 1.5\n 3 0 0 3\n\n"
      "ELEM\n 1 0 1 1 2\n 2 0 1 2 3\n\nMATE,1\n FRAMe\n RESUltant STIFfness 1e6 1e6 1e3\n"
      " SOFTening LINEar 100 -1e3 0.5 0 500\n\nEND\n",
      15, 34, "the shortest piece Lb = 500 is longer than the longest member");
}

// A study whose runs fail names the unit warnings in its message, as a run
// that fails does (decks/errors/section_units_failure.inp).
TEST(SectionUnits, AFailedStudyNamesTheUnitWarnings) {
  testing::DeckTempDir dir;
  const std::string deck =
      "SWEEp\n  P = 60 70\n\n"  // lines 1-3
      "FEAP * * fy in MPa\n  0 0 0 2 3 2\n\nCOORdinates\n  1 0 0 0\n  2 0 0 1.5\n  3 0 0 3\n\n"
      "ELEMents\n  1 0 1 1 2\n  2 0 1 2 3\n\nMATErial,1\n  FRAMe\n"  // lines 4-17
      "    SECTion RECTangular 0.3 0.5 30e3 500\n"                   // line 18, fy at 38
      "    REBAr 0.05 9.42e-4 0.45 9.42e-4\n    STIRrups 1e-4 0.2\n\n"
      "BOUNdary\n  1 0 1 1 1\n\nFORCe\n  3 0 P 0 0\n\nEND\n"
      "BATCh\n  PROP,,1\n  DT,,0.25\n  LOOP,,4\n    TIME\n    LOOP,,30\n      TANG,,1\n"
      "    NEXT\n  NEXT\nEND\n\nSTOP\n";
  const auto r = testing::runDeckText(dir, "fy_mpa.inp", deck);
  EXPECT_EQ(r.outcome.exitCode, kExitAnalysisFailed) << r.outcome.message;
  EXPECT_NE(r.outcome.message.find("2 of 2 runs of the study failed"), std::string::npos)
      << r.outcome.message;
  EXPECT_NE(
      r.outcome.message.find("advice: the deck's warnings name values that look like "
                             "another unit (" +
                             (dir.path() / "fy_mpa.inp").string() + ":18:38): check them first"),
      std::string::npos)
      << r.outcome.message;
  ASSERT_EQ(r.outcome.warnings.size(), 1u);
  EXPECT_TRUE(r.outcome.warnings[0].unit);
}

TEST(SectionUnits, MembersAreElementsInLineOfOneSet) {
  // A portal: columns of 3 m in two elements each, a beam of 4 m in two; a
  // brace of set 2 across it.
  const Deck d = parseDeckText(
      "FEAP * * x\n0 0 0 2 3 2\nCOOR\n 1 0 0 0\n 2 0 0 1.5\n 3 0 0 3\n 4 0 2 3\n 5 0 4 3\n"
      " 6 0 4 1.5\n 7 0 4 0\n\nELEM\n 1 0 1 1 2\n 2 0 1 2 3\n 3 0 1 3 4\n 4 0 1 4 5\n"
      " 5 0 1 5 6\n 6 0 1 6 7\n 7 0 2 1 5\n\n"
      "MATE,1\n FRAMe\n RESUltant STIFfness 1e6 1e6 1e3\n\n"
      "MATE,2\n FRAMe\n RESUltant STIFfness 1e6 1e6 1e3\n\nEND\n",
      "t.inp");
  Parameters params;
  const Model m = buildModel(std::get<Problem>(d.items.at(0)), params, nullptr, nullptr);
  const auto longest = longestMembers(m);
  ASSERT_EQ(longest.size(), 2u);
  EXPECT_DOUBLE_EQ(longest.at(1), 4.0);  // the beam; the columns turn at the corners
  EXPECT_DOUBLE_EQ(longest.at(2), 5.0);
}

}  // namespace
}  // namespace c2d
