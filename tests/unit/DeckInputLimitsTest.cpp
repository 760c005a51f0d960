// Deck reading on every input: a byte-order mark, a directory for a deck, an
// empty deck, numbers near 2^31 in generation, LOOP nesting, FEAP's keyword
// control record, POLAr and SHIFt, warnings, and file-name-safe run tags.
#include <gtest/gtest.h>

#include <climits>
#include <cmath>

#include "macro/deck/DeckParser.h"
#include "macro/mesh/ParseDeck.h"
#include "macro/deck/DeckReader.h"
#include "macro/deck/Limits.h"
#include "macro/mesh/MeshBinder.h"
#include "macro/deck/SolutionCommand.h"
#include "macro/draws/Sweep.h"
#include "macro/deck/Warnings.h"
#include "tests/unit/DeckTestSupport.h"

namespace c2d {
namespace {

using testing::DeckTempDir;
using testing::expectDeckError;

const char* kCantilever =
    "COOR\n 1 1 0 0\n 3 0 2 0\n\nELEM\n 1 1 1 1 2\n 2 0 1 2 3\n\n"
    "MATE,1\n FRAMe\n RESUltant STIFfness 1e6 1e6 1e3\n\nBOUN\n 1 0 1 1 1\n\n";

Model buildText(const std::string& text, Warnings* warnings = nullptr) {
  const Deck d = parseDeckText(text, "t.inp");
  Parameters params;
  MeshFacts facts;
  facts.warnings = warnings;
  return buildModel(std::get<Problem>(d.items.at(0)), params, nullptr, &facts);
}

TEST(DeckInput, ByteOrderMarkIsSkipped) {
  const auto recs = DeckReader::readString(
      "\xEF\xBB\xBF"
      "FEAP * * x\n",
      "t.inp");
  ASSERT_EQ(recs.size(), 1u);
  EXPECT_EQ(recs[0].text(0), "FEAP");
  EXPECT_EQ(recs[0][0].loc.col, 1);
}

TEST(DeckInput, DirectoryIsNotADeck) {
  DeckTempDir dir;
  EXPECT_THROW(DeckReader::readFile(dir.path().string()), DeckError);
  const std::string main = dir.write("main.inp", "INCLude .\n");
  expectDeckError([&] { DeckReader::readFile(main); }, main, 1, 9, "is a directory");
  const std::string dev = dir.write("dev.inp", "INCLude /dev/zero\n");
  expectDeckError([&] { DeckReader::readFile(dev); }, dev, 1, 9, "is not a regular file");
}

TEST(DeckInput, EmptyDeckAndDeckWithoutProblem) {
  expectDeckError([] { parseDeckText("", "e.inp"); }, "e.inp", 1, 1, "the deck is empty");
  expectDeckError([] { parseDeckText("\n\n", "e.inp"); }, "e.inp", 1, 1, "the deck is empty");
  expectDeckError([] { parseDeckText("PARA\n a = 1\n\nSTOP\n", "e.inp"); }, "e.inp", 1, 1,
                  "holds no problem");
}

TEST(DeckInput, TopLevelLoopNestingIsBounded) {
  std::string text;
  for (int i = 0; i <= DeckLimits::kMaxLoopDepth; ++i) text += "LOOP,,1\n";
  expectDeckError([&] { parseDeckText(text, "n.inp"); }, "n.inp", DeckLimits::kMaxLoopDepth + 1, 1,
                  "nested more than");
}

TEST(DeckInput, BatchLoopNestingIsBounded) {
  std::vector<Record> cmds;
  for (int i = 0; i < 20000; ++i) cmds.push_back(DeckReader::lexLine("LOOP,,1", "b.inp", i + 1));
  for (int i = 0; i < 20000; ++i) cmds.push_back(DeckReader::lexLine("NEXT", "b.inp", 20001 + i));
  SolutionCommands table;
  Parameters params;
  expectDeckError([&] { bindBatch(cmds, {}, table, params); }, "b.inp",
                  DeckLimits::kMaxLoopDepth + 1, 1, "nested more than");
}

TEST(DeckInput, GenerationIncrementsNearIntMaxGenerateNothing) {
  const std::string big = std::to_string(INT_MAX);
  const Model m = buildText("FEAP * * x\n0 0 0 2 3 2\nCOOR\n 1 " + big +
                            " 0 0\n 2 0 1 0\n 3 0 2 0\n\n"
                            "ELEM\n 1 1 1 1 2\n 2 0 1 2 3\n\n"
                            "MATE,1\n FRAMe\n RESUltant STIFfness 1e6 1e6 1e3\n\n"
                            "BOUN\n 1 " +
                            big +
                            " 1 1 1\n 3 0 0 0 0\n\n"
                            "FORC\n 1 -" +
                            big + " 0 0 0\n 3 0 0 -1 0\n\nEND\n");
  ASSERT_EQ(m.numNodes(), 3);
  EXPECT_DOUBLE_EQ(m.coord(1).x(), 1.0);
  EXPECT_EQ(m.bound(1)[0], 0);
  EXPECT_EQ(m.force(1)[1], 0.0);
  EXPECT_EQ(m.force(2)[1], -1.0);
}

TEST(DeckInput, NumbersBeyondTheLimitsAreLocated) {
  expectDeckError(
      [] {
        buildText(std::string("FEAP * * x\n0 0 0 2 3 2\n") + kCantilever +
                  "COOR\n 1000000000 0 0 0\n\nEND\n");
      },
      "t.inp", 19, 2, "is beyond the largest this program takes");
  expectDeckError([] { buildText("FEAP * * x\n2000000000 0 0 2 3 2\nEND\n"); }, "t.inp", 2, 1,
                  "numnp 2000000000 is beyond");
  expectDeckError(
      [] {
        buildText(
            "FEAP * * x\n0 0 0 2 3 2\nBLOCk\n CART 2147483647 0 1 1 1\n 1 0 0\n 2 1 0\n\n"
            "END\n");
      },
      "t.inp", 4, 7, "the block's last node 2147483648");
  expectDeckError(
      [] {
        buildText("FEAP * * x\n0 0 0 2 3 2\nBLOCk\n CART -3 0 1 1 1\n 1 0 0\n 2 1 0\n\nEND\n");
      },
      "t.inp", 4, 7, "at least one element");
}

TEST(DeckInput, KeywordControlRecord) {
  const Deck d = parseDeckText(std::string("FEAP * * x\n NODEs=3 ELEMents=2\n MATErial 1\n"
                                           " ndm 2 ndf 3 nen 2\n\n") +
                                   kCantilever + "END\n",
                               "k.inp");
  const Problem& p = std::get<Problem>(d.items.at(0));
  ASSERT_EQ(p.controlKeywords.size(), 3u);
  EXPECT_TRUE(p.control.blank());
  Parameters params;
  Model model;
  MeshBinder binder(model, params, nullptr);
  const ControlData c = binder.setControl(p.controlKeywords);
  EXPECT_EQ(c.numnp, 3);
  EXPECT_EQ(c.numel, 2);
  EXPECT_EQ(c.nummat, 1);
  EXPECT_EQ(model.numNodes(), 3);

  expectDeckError([] { parseDeckText("FEAP * * x\n NODES 3\nCOOR\n 1 0 0 0\n\nEND\n", "k.inp"); },
                  "k.inp", 3, 1, "unknown control keyword 'COOR'");
  expectDeckError([] { parseDeckText("FEAP * * x\n NODES\n\nEND\n", "k.inp"); }, "k.inp", 2, 7,
                  "has no value");
  expectDeckError([] { buildText("FEAP * * x\n NODES 3 dofs 6\n\nEND\n"); }, "t.inp", 2, 15,
                  "ndf must be 3");
  expectDeckError([] { buildText("FEAP * * x\n NODES 3\n numnp 4\n\nEND\n"); }, "t.inp", 3, 2,
                  "given twice");
}

TEST(DeckInput, PolarCoordinatesAboutTheShiftOrigin) {
  const Model m = buildText(
      "FEAP * * x\n0 0 0 2 3 2\nCOOR\n 1 1 2 0\n 3 0 2 90\n 4 0 1 180\n\nSHIFt\n 1 1\n"
      "POLAr\n NODE 1 3 1\n NODE 4 0 0 0.5\n\nELEM\n 1 1 1 1 2\n 2 0 1 2 3\n 3 0 1 4 1\n\n"
      "MATE,1\n FRAMe\n RESUltant STIFfness 1e6 1e6 1e3\n\nEND\n");
  EXPECT_NEAR(m.coord(0).x(), 3, 1e-14);
  EXPECT_NEAR(m.coord(0).y(), 1, 1e-14);
  EXPECT_NEAR(m.coord(1).x(), 1 + std::sqrt(2.0), 1e-14);
  EXPECT_NEAR(m.coord(1).y(), 1 + std::sqrt(2.0), 1e-14);
  EXPECT_NEAR(m.coord(2).x(), 1, 1e-14);
  EXPECT_NEAR(m.coord(2).y(), 3, 1e-14);
  EXPECT_NEAR(m.coord(3).x(), 0.5, 1e-14);
  EXPECT_NEAR(m.coord(3).y(), 1, 1e-14);

  // SHIFt on the command record, ALL; a node is converted once.
  const Model n = buildText(
      "FEAP * * x\n0 0 0 2 3 2\nCOOR\n 1 0 1 90\n 2 0 1 0\n\nSHIFt,2,0\nPOLAr\n ALL\n\n"
      "ELEM\n 1 1 1 1 2\n\nMATE,1\n FRAMe\n RESUltant STIFfness 1e6 1e6 1e3\n\nEND\n");
  EXPECT_NEAR(n.coord(0).x(), 2, 1e-14);
  EXPECT_NEAR(n.coord(0).y(), 1, 1e-14);
  EXPECT_NEAR(n.coord(1).x(), 3, 1e-14);
  expectDeckError(
      [] {
        buildText(
            "FEAP * * x\n0 0 0 2 3 2\nCOOR\n 1 0 1 90\n 2 0 1 0\n\nPOLAr\n ALL\n NODE 1\n\n"
            "END\n");
      },
      "t.inp", 9, 7, "converted already (line 8)");
}

TEST(DeckInput, WarningsAreLocatedAndCountedOnce) {
  Warnings w;
  const std::string text =
      std::string("FEAP * * x\n0 0 0 2 3 2\n") + kCantilever + "COOR\n 4 1 5 5\n 6 0 7 7\n\nEND\n";
  buildText(text, &w);
  buildText(text, &w);  // a problem bound twice (a top-level loop) warns once
  ASSERT_EQ(w.list().size(), 2u);
  EXPECT_EQ(w.list()[0].loc.str(), "t.inp:19:2");
  EXPECT_NE(w.list()[0].str().find("t.inp:19:2: warning: nodes 4, 5 are used by no element"),
            std::string::npos)
      << w.list()[0].str();
  EXPECT_NE(w.list()[1].str().find("t.inp:20:2: warning: node 6 is used by no element"),
            std::string::npos)
      << w.list()[1].str();
}

TEST(DeckInput, RunTagsFitFileNames) {
  EXPECT_EQ(fitFileStem("deck_ks=-393"), "deck_ks=-393");
  const std::string a = "deck_" + std::string(300, 'k') + "=1",
                    b = "deck_" + std::string(300, 'k') + "=2";
  EXPECT_EQ(fitFileStem(a).size(), 160u);
  EXPECT_NE(fitFileStem(a), fitFileStem(b));
  EXPECT_EQ(fitFileStem(a), fitFileStem(a));
}

}  // namespace
}  // namespace c2d
