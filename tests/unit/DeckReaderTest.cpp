// Records and fields: separators, empty fields, comments, CRLF and tabs,
// columns, the four-character rule, INCLude expansion with locations.
#include <gtest/gtest.h>

#include "macro/deck/DeckReader.h"
#include "tests/unit/DeckTestSupport.h"

namespace c2d {
namespace {

using testing::DeckTempDir;
using testing::expectDeckError;

std::vector<std::string> texts(const Record& r) {
  std::vector<std::string> t;
  for (const auto& f : r.fields) t.push_back(f.text);
  return t;
}

std::vector<int> cols(const Record& r) {
  std::vector<int> c;
  for (const auto& f : r.fields) c.push_back(f.loc.col);
  return c;
}

TEST(RecordLexer, BlanksCommasAndEqualsSeparate) {
  const Record r = DeckReader::lexLine("COOR, 1   2,,3 = 4", "f", 7);
  EXPECT_EQ(texts(r), (std::vector<std::string>{"COOR", "1", "2", "", "3", "4"}));
  EXPECT_EQ(cols(r), (std::vector<int>{1, 7, 11, 13, 14, 18}));
  EXPECT_EQ(r.loc.line, 7);
  EXPECT_EQ(r[0].loc.file, "f");
  EXPECT_EQ(r[5].loc.line, 7);
}

TEST(RecordLexer, TwoCommasMakeAnEmptyField) {
  EXPECT_EQ(texts(DeckReader::lexLine("DT,,0.01", "f", 1)),
            (std::vector<std::string>{"DT", "", "0.01"}));
  EXPECT_EQ(texts(DeckReader::lexLine("TANG , , 1", "f", 1)),
            (std::vector<std::string>{"TANG", "", "1"}));
  EXPECT_EQ(texts(DeckReader::lexLine(",5", "f", 1)), (std::vector<std::string>{"", "5"}));
  // A run of blanks is one separator, a trailing separator adds nothing.
  EXPECT_EQ(texts(DeckReader::lexLine("   a     b   ,", "f", 1)),
            (std::vector<std::string>{"a", "b"}));
}

TEST(RecordLexer, CommentsEndTheRecord) {
  const Record r = DeckReader::lexLine("  1 0 2.5 ! node 1, x = 2.5", "f", 3);
  EXPECT_EQ(texts(r), (std::vector<std::string>{"1", "0", "2.5"}));
  EXPECT_EQ(r.lineText(), "  1 0 2.5");
  EXPECT_TRUE(DeckReader::lexLine("! only a comment", "f", 1).blank());
  EXPECT_TRUE(DeckReader::lexLine("", "f", 1).blank());
  EXPECT_TRUE(DeckReader::lexLine(" \t  ", "f", 1).blank());
}

TEST(RecordLexer, TabsAndCrLfAreAccepted) {
  const auto recs = DeckReader::readString("a\tb\r\n\r\n\tc,d\r\n", "deck.inp");
  ASSERT_EQ(recs.size(), 3u);
  EXPECT_EQ(texts(recs[0]), (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(cols(recs[0]), (std::vector<int>{1, 3}));
  EXPECT_TRUE(recs[1].blank());  // kept: a blank record ends data sets
  EXPECT_EQ(texts(recs[2]), (std::vector<std::string>{"c", "d"}));
  EXPECT_EQ(cols(recs[2]), (std::vector<int>{2, 4}));
  EXPECT_EQ(recs[2].loc.line, 3);
  EXPECT_EQ(recs[2].lineText(), " c,d");  // tab shown as a blank, so carets line up
}

TEST(RecordLexer, LongRecordIsAnError) {
  const std::string ok(256, 'x');
  EXPECT_NO_THROW(DeckReader::lexLine(ok, "f", 1));
  expectDeckError([] { DeckReader::lexLine(std::string(257, 'x'), "long.inp", 4); }, "long.inp", 4,
                  257, "longer than 256");
}

TEST(RecordLexer, ControlCharacterIsAnError) {
  expectDeckError([] { DeckReader::lexLine(std::string("ab\x01") + "c", "f", 2); }, "f", 2, 3,
                  "control character");
}

TEST(RecordLexer, FourCharacterRule) {
  EXPECT_TRUE(keywordMatches("COOR", "COORdinates"));
  EXPECT_TRUE(keywordMatches("coordinates", "COORdinates"));
  EXPECT_TRUE(keywordMatches("Coord", "COORdinates"));
  EXPECT_TRUE(keywordMatches("coorXYZ", "COORdinates"));
  EXPECT_FALSE(keywordMatches("COO", "COORdinates"));
  EXPECT_FALSE(keywordMatches("CORD", "COORdinates"));
  // Names shorter than four characters must stand alone.
  EXPECT_TRUE(keywordMatches("end", "END"));
  EXPECT_TRUE(keywordMatches("Dt", "DT"));
  EXPECT_FALSE(keywordMatches("ends", "END"));
  EXPECT_FALSE(keywordMatches("dtx", "DT"));
  EXPECT_TRUE(DeckReader::lexLine("Elements", "f", 1).is("ELEMents"));
  EXPECT_FALSE(DeckReader::lexLine("", "f", 1).is("ELEMents"));
}

TEST(RecordLexer, ExcerptPutsACaretUnderTheColumn) {
  const Record r = DeckReader::lexLine("COOR 1 2", "f", 1);
  EXPECT_EQ(r.excerpt(6), "COOR 1 2\n         ^");
  EXPECT_EQ(r[2].excerpt(), "COOR 1 2\n           ^");
}

TEST(RecordInclude, NestedIncludesKeepTheirOwnLocations) {
  DeckTempDir dir;
  const std::string main = dir.write("main.inp", "first\nINCLude,sub/a.inc ! the mesh\nlast\n");
  dir.write("sub/a.inc", "a1 x\n  include b.inc\n\na2\n");  // relative to sub/
  dir.write("sub/b.inc", "b1\n   b2  y\n");
  const auto recs = DeckReader::readFile(main);
  ASSERT_EQ(recs.size(), 7u);
  const std::string a = (dir.path() / "sub/a.inc").lexically_normal().string();
  const std::string b = (dir.path() / "sub/b.inc").lexically_normal().string();
  EXPECT_EQ(recs[0].text(0), "first");
  EXPECT_EQ(recs[0].loc.file, main);
  EXPECT_EQ(recs[1].text(0), "a1");
  EXPECT_EQ(recs[1].loc.file, a);
  EXPECT_EQ(recs[1].loc.line, 1);
  EXPECT_EQ(recs[2].text(0), "b1");
  EXPECT_EQ(recs[2].loc.file, b);
  EXPECT_EQ(recs[3].text(1), "y");
  EXPECT_EQ(recs[3][1].loc.file, b);
  EXPECT_EQ(recs[3][1].loc.line, 2);
  EXPECT_EQ(recs[3][1].loc.col, 8);
  EXPECT_TRUE(recs[4].blank());
  EXPECT_EQ(recs[4].loc.file, a);
  EXPECT_EQ(recs[4].loc.line, 3);
  EXPECT_EQ(recs[5].text(0), "a2");
  EXPECT_EQ(recs[5].loc.line, 4);
  EXPECT_EQ(recs[6].text(0), "last");
  EXPECT_EQ(recs[6].loc.file, main);
  EXPECT_EQ(recs[6].loc.line, 3);
}

TEST(RecordInclude, MissingFileIsAnErrorAtTheIncludeRecord) {
  DeckTempDir dir;
  const std::string main = dir.write("main.inp", "a\n\n  INCL,   nothere.inc\n");
  expectDeckError([&] { DeckReader::readFile(main); }, main, 3, 11, "cannot open included file");
}

TEST(RecordInclude, ErrorInsideAnIncludedFileNamesThatFile) {
  DeckTempDir dir;
  const std::string main = dir.write("main.inp", "a\nINCLude inc.inp\n");
  const std::string inc = dir.write("inc.inp", "ok\n" + std::string(300, 'z') + "\n");
  expectDeckError([&] { DeckReader::readFile(main); }, (dir.path() / "inc.inp").string(), 2, 257,
                  "longer than 256");
  (void)inc;
}

TEST(RecordInclude, SelfInclusionIsAnError) {
  DeckTempDir dir;
  const std::string main = dir.write("loop.inp", "INCLude loop.inp\n");
  expectDeckError([&] { DeckReader::readFile(main); }, main, 1, 9, "includes itself");
}

TEST(RecordInclude, MissingDeckIsAnError) {
  EXPECT_THROW(DeckReader::readFile("/nonexistent/deck.inp"), DeckError);
}

}  // namespace
}  // namespace c2d
