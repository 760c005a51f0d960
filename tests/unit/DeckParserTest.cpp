// Deck structure (problems, mesh data sets, BATCh blocks, top-level LOOP) and
// the parse errors of a dozen bad decks (the command registry: CommandSpecTest).
#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>

#include "macro/deck/CommandSpec.h"
#include "macro/deck/DeckParser.h"
#include "macro/mesh/ParseDeck.h"
#include "macro/deck/DeckReader.h"
#include "macro/mesh/MeshCommands.h"
#include "tests/unit/DeckTestSupport.h"

namespace c2d {
namespace {

using testing::DeckTempDir;
using testing::expectDeckError;

const char* kDeck = R"(! a small frame
PARAmeter
  L = 4.0
  ks_beam = -2*L

feap * * Portal frame
  0 0 0 2 3 2
COORdinates
  1 1 0 0
  3 0 L 0

ELEM
  1 1 1 1 2
  2 0 1 2 3

MATErial,1 beams and columns
  FRAMe
    ELAStic ISOTropic 30e6 0.2
    CROSs section 0.12 1.6e-3

PARA
  p = 2

BOUN
  1 0 1 1 1

GRAVity,,0,-9.81
END

BATCh
  PROP,,1
  DT,,0.1

  LOOP,,10
    TIME
    TANG,,1
  NEXT
END
 1 2 0 10 0 1

BATCh
  DISP,ALL
END
STOP
)";

TEST(DeckParserStructure, ProblemMeshAndBatches) {
  const Deck d = parseDeckText(kDeck, "portal.inp");
  EXPECT_EQ(d.path, "portal.inp");
  ASSERT_EQ(d.items.size(), 2u);
  const auto& params = std::get<ParamBlock>(d.items[0]);
  ASSERT_EQ(params.assigns.size(), 2u);
  EXPECT_EQ(params.assigns[1].name, "ks_beam");
  Parameters p;
  params.apply(p);
  EXPECT_EQ(p.get("KS_BEAM"), -8.0);

  const auto& pr = std::get<Problem>(d.items[1]);
  EXPECT_EQ(pr.title, "* * Portal frame");
  EXPECT_EQ(pr.control.size(), 6u);
  EXPECT_EQ(pr.control.loc.line, 7);
  ASSERT_EQ(pr.mesh.size(), 6u);
  const auto& coor = std::get<MeshCommand>(pr.mesh[0]);
  EXPECT_TRUE(coor.head.is("COORdinates"));
  ASSERT_EQ(coor.data.size(), 2u);
  EXPECT_EQ(coor.data[1].text(2), "L");
  const auto& mate = std::get<MeshCommand>(pr.mesh[2]);
  EXPECT_EQ(mate.data.size(), 3u);  // FRAMe + two sub-records
  EXPECT_TRUE(std::holds_alternative<ParamBlock>(pr.mesh[3]));
  const auto& grav = std::get<MeshCommand>(pr.mesh[5]);
  EXPECT_TRUE(grav.head.is("GRAVity"));
  EXPECT_TRUE(grav.data.empty());
  EXPECT_EQ(pr.meshEnd.loc.line, 28);

  ASSERT_EQ(pr.batches.size(), 2u);
  const auto& b = pr.batches[0];
  ASSERT_EQ(b.commands.size(), 6u);  // blank record dropped
  EXPECT_EQ(b.commands[2].text(0), "LOOP");
  EXPECT_EQ(b.end.loc.line, 38);
  ASSERT_EQ(b.data.size(), 2u);  // the data record and the blank that ends it
  EXPECT_EQ(b.data[0].text(5), "1");
  EXPECT_TRUE(b.data[1].blank());
  EXPECT_EQ(pr.batches[1].commands.size(), 1u);
  EXPECT_TRUE(pr.batches[1].data.empty());
  ASSERT_TRUE(d.stop.has_value());
  EXPECT_EQ(d.stop->loc.line, 44);
}

TEST(DeckParserStructure, TopLevelLoopAroundProblems) {
  const char* text = R"(PARA
  h = 0

LOOP,,3
  PARA
    h = h + 1

  FEAP * * run
    0 0 0 2 3 2
  END
  BATCh
    TANG,,1
  END

  LOOP,inner,2
  FEAP * * second
    0 0 0 2 3 2
  END
  NEXT
NEXT

FEAP * * after the loop
  0 0 0 2 3 2
END
STOP
)";
  const Deck d = parseDeckText(text, "loop.inp");
  ASSERT_EQ(d.items.size(), 3u);
  const auto& loop = std::get<TopLoop>(d.items[1]);
  EXPECT_EQ(loop.count.eval({}), 3.0);
  EXPECT_EQ(loop.head.loc.line, 4);
  EXPECT_EQ(loop.next.loc.line, 20);
  ASSERT_EQ(loop.body.size(), 3u);
  EXPECT_TRUE(std::holds_alternative<ParamBlock>(loop.body[0]));
  const auto& run = std::get<Problem>(loop.body[1]);
  EXPECT_EQ(run.title, "* * run");
  ASSERT_EQ(run.batches.size(), 1u);
  ASSERT_EQ(run.batches[0].data.size(), 1u);  // the blank record, then the inner LOOP ends the data
  EXPECT_TRUE(run.batches[0].data[0].blank());
  const auto& inner = std::get<TopLoop>(loop.body[2]);
  EXPECT_EQ(inner.count.eval({}), 2.0);
  ASSERT_EQ(inner.body.size(), 1u);
  EXPECT_EQ(std::get<Problem>(inner.body[0]).title, "* * second");
  EXPECT_EQ(std::get<Problem>(d.items[2]).title, "* * after the loop");

  // The parameter study: evaluate the loop as the interpreter would.
  Parameters p;
  std::get<ParamBlock>(d.items[0]).apply(p);
  for (int i = 0; i < loop.count.evalInt(p, "loop count"); ++i)
    std::get<ParamBlock>(loop.body[0]).apply(p);
  EXPECT_EQ(p.get("h"), 3.0);
}

TEST(DeckParserStructure, ParameterBlockBeforeTheNextProblemIsTopLevel) {
  const char* text = R"(FEAP * * one
  0 0 0 2 3 2
END
BATCh
  MESH
  PARA
END
FORC
  1 0 1 0 0

PARA
  x = 2

END
a = 5

CONStant
  y = 3

FEAP * * two
  0 0 0 2 3 2
END
STOP
)";
  const Deck d = parseDeckText(text, "two.inp");
  ASSERT_EQ(d.items.size(), 3u);
  const auto& one = std::get<Problem>(d.items[0]);
  ASSERT_EQ(one.batches.size(), 1u);
  // MESH data (with its own PARA block and END) and PARA data stay with the batch.
  EXPECT_EQ(one.batches[0].data.size(), 9u);
  EXPECT_TRUE(std::get<ParamBlock>(d.items[1]).head.is("CONStant"));
  EXPECT_EQ(std::get<Problem>(d.items[2]).title, "* * two");
}

TEST(DeckParserStructure, CaseAndAbbreviationsOfStructuralWords) {
  const Deck d = parseDeckText(
      "Feap * * x\n 0 0 0 2 3 2\ncoordinates\n 1 0 0 0\n\nend\nbatch\n tang\nend\nstop\n", "c.inp");
  ASSERT_EQ(d.items.size(), 1u);
  EXPECT_EQ(std::get<Problem>(d.items[0]).batches.size(), 1u);
  EXPECT_TRUE(d.stop.has_value());
}

TEST(DeckParserStructure, AssignmentRecords) {
  const Record r = DeckReader::lexLine("  Mu = 2*(a + b) ! comment", "f", 3);
  const ParamAssign a = DeckParser::parseAssignment(r);
  EXPECT_EQ(a.name, "mu");
  EXPECT_EQ(a.value.text(), "2*(a + b)");
  Parameters p;
  p.set("a", 1);
  p.set("b", 2);
  EXPECT_EQ(a.value.eval(p), 6.0);
  EXPECT_EQ(a.value.loc().col, 8);
  expectDeckError([] { DeckParser::parseAssignment(DeckReader::lexLine("2x = 3", "f", 1)); }, "f",
                  1, 1, "not a parameter name");
  expectDeckError([] { DeckParser::parseAssignment(DeckReader::lexLine("x =", "f", 1)); }, "f", 1,
                  4, "has no value");
}

// --- errors -----------------------------------------------------------------

struct BadDeck {
  const char* name;
  const char* text;
  int line, col;
  const char* message;
};

const BadDeck kBadDecks[] = {
    {"unknown_command", "FEAP * * x\n0 0 0 2 3 2\n  CORDinates\n1 0 0 0\n\nEND\n", 3, 3,
     "unknown mesh command 'CORDinates'"},
    {"mesh_without_end", "FEAP * * x\n0 0 0 2 3 2\nCOOR\n1 0 0 0\n\nBATCh\nEND\n", 6, 1,
     "missing END of the mesh input"},
    {"batch_without_end", "FEAP * * x\n0 0 0 2 3 2\nEND\n\n BATCh\n TANG\n", 5, 2,
     "BATCh block without END"},
    {"loop_without_next", "LOOP,,2\nFEAP * * x\n0 0 0 2 3 2\nEND\n", 1, 1, "LOOP without NEXT"},
    {"next_without_loop", "FEAP * * x\n0 0 0 2 3 2\nEND\nBATCh\nEND\n\n  NEXT\nSTOP\n", 7, 3,
     "NEXT without LOOP"},
    {"stop_inside_loop", "LOOP,,2\nFEAP * * x\n0 0 0 2 3 2\nEND\nSTOP\n", 5, 1,
     "STOP inside the LOOP"},
    {"data_set_not_ended",
     "FEAP * * x\n0 0 0 2 3 2\nCOOR\n1 0 0 0\n2 0 1 0\nELEM\n1 0 1 1 2\n\nEND\n", 6, 1,
     "the data set of 'COOR' (line 3) is not ended by a blank record"},
    {"data_set_not_ended_at_eof", "FEAP * * x\n0 0 0 2 3 2\n\nBOUN\n1 0 1 1 1\n", 4, 1,
     "not ended by a blank record (end of file)"},
    {"syntax_error_in_data", "FEAP * * x\n0 0 0 2 3 2\nCOOR\n1 0 2*(3 0\n\nEND\n", 4, 7,
     "'(' is never closed"},
    {"param_block_not_ended", "PARA\n a = 1\nFEAP * * x\n0 0 0 2 3 2\nEND\n", 3, 1,
     "PARAmeter block (line 1) is not ended"},
    {"missing_control_record", "FEAP * * x\nCOORdinates\n1 0 0 0\n\nEND\n", 2, 1,
     "missing control record"},
    {"data_outside_data_set", "FEAP * * x\n0 0 0 2 3 2\nCOOR\n1 0 0 0\n\n2 0 1 0\n\nEND\n", 6, 1,
     "data record outside a data set"},
    {"unexpected_top_level", "COOR\n1 0 0 0\n", 1, 1, "unexpected record 'COOR'"},
    {"bad_parameter_name", "PARA\n 3x = 2\n\n", 2, 2, "not a parameter name"},
    {"loop_count_missing", "LOOP\nNEXT\n", 1, 5, "LOOP needs a repeat count"},
    {"no_mesh_end", "FEAP * * x\n0 0 0 2 3 2\nCOOR\n1 0 0 0\n\n", 1, 1, "has no END"},
    {"garbage_after_mesh", "FEAP * * x\n0 0 0 2 3 2\nEND\nTANG\n", 4, 1, "expected BATCh"},
    {"syntax_error_in_control", "FEAP * * x\n0 0 0 2 3 2+\nEND\n", 2, 13, "ends too early"},
    {"ensemble_inside_mesh", "FEAP * * x\n0 0 0 2 3 2\n\nENSEmble,,2\n mu = UNIForm 0 1\n\nEND\n",
     4, 1, "ENSEmble inside the mesh input of the problem of"},
    {"sweep_inside_mesh", "FEAP * * x\n0 0 0 2 3 2\nSWEEp\n a = 1 2\n\nEND\n", 3, 1,
     "a study block stands at the top level, before the FEAP record"},
    {"missing_include", "FEAP * * x\n0 0 0 2 3 2\nINCLude mesh.inc\nEND\n", 3, 9,
     "cannot open included file"},
};

class DeckParserErrors : public ::testing::TestWithParam<BadDeck> {};

TEST_P(DeckParserErrors, ReportsFileLineColumn) {
  const BadDeck& b = GetParam();
  DeckTempDir dir;
  const std::string path = dir.write(std::string(b.name) + ".inp", b.text);
  expectDeckError([&] { parseDeck(path); }, path, b.line, b.col, b.message);
}

INSTANTIATE_TEST_SUITE_P(DeckParserBadDecks, DeckParserErrors, ::testing::ValuesIn(kBadDecks),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(DeckParserErrorsDetail, UnknownCommandHintAndText) {
  try {
    parseDeckText("FEAP * * x\n0 0 0 2 3 2\n  CORDinates\n", "h.inp");
    FAIL() << "no error";
  } catch (const DeckError& e) {
    EXPECT_EQ(e.hint(), "did you mean 'COORdinates'?");
    EXPECT_EQ(e.text(), "  CORDinates\n      ^");
    EXPECT_EQ(std::string(e.what()),
              "h.inp:3:3: error: unknown mesh command 'CORDinates'\n    "
              "  CORDinates\n      ^\n    did you mean 'COORdinates'?");
  }
}

TEST(DeckParserErrorsDetail, ErrorInIncludedMeshNamesTheIncludedFile) {
  DeckTempDir dir;
  const std::string main =
      dir.write("main.inp", "FEAP * * x\n0 0 0 2 3 2\nINCLude parts/mesh.inc\nEND\nSTOP\n");
  dir.write("parts/mesh.inc", "COOR\n1 0 0 0\n\nELEM\n 1 0 1 1 )\n\n");
  expectDeckError([&] { parseDeck(main); }, (dir.path() / "parts/mesh.inc").string(), 5, 10,
                  "expected a value before ')'");
}

}  // namespace
}  // namespace c2d
