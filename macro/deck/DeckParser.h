#pragma once
// The second phase: the flat record stream to the deck structure (Deck.h).
// Problems, mesh commands and their data sets, BATCh blocks and top-level
// LOOP/NEXT are matched here; every expression is parsed, so that any syntax
// error, unknown mesh command, unmatched LOOP/NEXT or missing END is reported
// with its file:line:col before anything is computed.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "macro/deck/CommandSpec.h"
#include "macro/deck/Deck.h"
#include "macro/deck/Record.h"

namespace c2d {

class DeckParser {
 public:
  // meshCommands: the mesh command registry; subRecords: material sub-records
  // and element types (both from macro/mesh/MeshCommands.h; parseDeck in
  // macro/mesh/ParseDeck.h builds them).
  DeckParser(std::vector<Record> records, std::string path, const CommandRegistry& meshCommands,
             const CommandRegistry& subRecords);

  Deck parse();
  // Mesh commands alone (MESH re-entry): the items up to an END record or the end
  // of the records; non-blank records after that END are an error.
  std::vector<MeshItem> parseMeshInput();

  // One "name = expression" record (also used for PARA in the solution phase).
  static ParamAssign parseAssignment(const Record& rec);
  // PARAmeter head record and the records up to (not including) the blank one.
  static ParamBlock parseParamBlock(const Record& head, const std::vector<Record>& body);
  // The count of a top-level LOOP record: LOOP,,n (or LOOP,n).
  static Expression loopCount(const Record& rec);

 private:
  bool atEnd() const { return pos_ >= records_.size(); }
  const Record& peek() const { return records_[pos_]; }
  const Record& next() { return records_[pos_++]; }
  void skipBlanks();

  std::vector<TopItem> parseTopItems(const Record* loopHead);
  ParamBlock parseParams();
  TopSweep parseSweep();
  TopItem parseEnsemble(bool inSweep);
  void parseStudyBody(std::vector<TopItem>& body, const Record& head, const char* what);
  Problem parseProblem();
  void parseMesh(Problem& p);
  void parseBatches(Problem& p);
  // false: no END before EOF. head: the problem's FEAP record (null for a MESH
  // re-entry's records), named by errors.
  bool parseMeshItems(std::vector<MeshItem>& items, Record* end, const Record* head);
  MeshCommand parseMeshCommand(const CommandSpec& spec);
  BatchBlock parseBatch();
  bool endsBatchData() const;
  bool topLevelParamsAhead() const;
  void checkDataRecord(const Record& rec, const Record& head, const CommandSpec& spec) const;
  // The record starts a mesh command, a structural word or a parameter block.
  bool startsItem(const Record& r) const;

  std::vector<Record> records_;
  std::string path_;
  const CommandRegistry& mesh_;
  const CommandRegistry& sub_;
  std::size_t pos_ = 0;
  int loopDepth_ = 0;  // top-level LOOPs open
};

// Index of a control keyword in the numeric control record (NODEs/NUMNp 0,
// ELEMents/NUMEl 1, MATErial/NUMMat 2, DIMEnsion/NDM 3, DOFS/NDF 4, ELNOdes/NEN
// 5, ADD/NAD 6, PROPortional/NPD 7, UPROportional/NUD 8), -1 for another word.
int controlKeywordIndex(std::string_view word);

}  // namespace c2d
