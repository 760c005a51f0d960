#include "macro/deck/DeckParser.h"

#include <algorithm>
#include <cctype>

#include "macro/deck/DeckReader.h"
#include "macro/deck/Limits.h"
#include "macro/deck/Parameters.h"
#include "macro/deck/StudyBlocks.h"

namespace c2d {

namespace {

// Words that structure a deck: a record starting with one of them is never data
// of a mesh command.
bool isStructural(const Record& r) {
  return r.is("FEAP") || r.is("BATCh") || r.is("STOP") || r.is("END") || r.is("LOOP") ||
         r.is("NEXT") || r.is("SWEEp") || r.is("ENSEmble");
}

bool isParamHead(const Record& r) { return r.is("PARAmeter") || r.is("CONStant"); }

}  // namespace

// FEAP's control keywords (pnewprob): four characters of the name, or the
// variable's name (NUMNp, NDM, ...).
int controlKeywordIndex(std::string_view word) {
  static const char* const names[][2] = {
      {"NODEs", "NUMNp"},   {"ELEMents", "NUMEl"},   {"MATErial", "NUMMat"},
      {"DIMEnsion", "NDM"}, {"DOFS", "NDF"},         {"ELNOdes", "NEN"},
      {"ADD", "NAD"},       {"PROPortional", "NPD"}, {"UPROportional", "NUD"}};
  for (int i = 0; i < 9; ++i)
    if (keywordMatches(word, names[i][0]) || keywordMatches(word, names[i][1])) return i;
  return -1;
}

namespace {

bool isControlKeyword(std::string_view word) { return controlKeywordIndex(word) >= 0; }

// Is the first field followed by '=' (then the record is an assignment, even if
// its name looks like a keyword)?
bool hasEquals(const Record& r) {
  if (r.blank() || !r.line) return false;
  const std::string& s = *r.line;
  std::size_t p = static_cast<std::size_t>(r[0].loc.col - 1) + r[0].text.size();
  while (p < s.size() && s[p] == ' ') ++p;
  return p < s.size() && s[p] == '=';
}

std::string where(const Record& r) { return "line " + std::to_string(r.loc.line); }

std::string lineRef(const Record& r) { return r.loc.file + ":" + std::to_string(r.loc.line); }

bool looksNumeric(const std::string& t) {
  return !t.empty() && (std::isdigit(static_cast<unsigned char>(t[0])) || t[0] == '.' ||
                        t[0] == '-' || t[0] == '+' || t[0] == '(');
}

}  // namespace

DeckParser::DeckParser(std::vector<Record> records, std::string path,
                       const CommandRegistry& meshCommands, const CommandRegistry& subRecords)
    : records_(std::move(records)), path_(std::move(path)), mesh_(meshCommands), sub_(subRecords) {}

void DeckParser::skipBlanks() {
  while (!atEnd() && peek().blank()) ++pos_;
}

namespace {

bool holdsProblem(const std::vector<TopItem>& items) {
  for (const TopItem& item : items) {
    if (std::holds_alternative<Problem>(item)) return true;
    if (const auto* loop = std::get_if<TopLoop>(&item); loop && holdsProblem(loop->body))
      return true;
    if (const auto* sweep = std::get_if<TopSweep>(&item); sweep && holdsProblem(sweep->body))
      return true;
    if (const auto* e = std::get_if<TopEnsemble>(&item); e && holdsProblem(e->body)) return true;
  }
  return false;
}

}  // namespace

Deck DeckParser::parse() {
  Deck deck;
  deck.path = path_;
  deck.items = parseTopItems(nullptr);
  if (!atEnd() && peek().is("STOP")) deck.stop = next();
  if (!holdsProblem(deck.items)) {
    const bool empty =
        std::all_of(records_.begin(), records_.end(), [](const Record& r) { return r.blank(); });
    throw DeckError({path_, 1, 1},
                    empty ? "the deck is empty" : "the deck holds no problem (no FEAP record)", {},
                    "a problem starts with a record 'FEAP * * title'");
  }
  return deck;
}

ParamAssign DeckParser::parseAssignment(const Record& rec) {
  const Field& name = rec[0];
  if (!Parameters::validName(name.text))
    throw DeckError(name.loc,
                    "expected 'name = expression', and '" + name.text + "' is not a parameter name",
                    rec.excerpt(name.loc),
                    "a name starts with a letter or '_' and goes on with letters, digits or '_'");
  if (rec.size() < 2 || rec[1].text.empty())
    throw DeckError(rec.fieldLoc(1), "parameter '" + name.text + "' has no value",
                    rec.excerpt(rec.fieldLoc(1)), "write " + name.text + " = expression");
  // The expression is the rest of the record: blanks inside it are allowed here.
  const std::string text = rec.restOfLine(1);
  ParamAssign a;
  a.name = toLower(name.text);
  a.value = Expression::parse(text, rec[1].loc, rec.line);
  a.record = rec;
  return a;
}

ParamBlock DeckParser::parseParamBlock(const Record& head, const std::vector<Record>& body) {
  ParamBlock b;
  b.head = head;
  for (const auto& r : body) b.assigns.push_back(parseAssignment(r));
  return b;
}

Expression DeckParser::loopCount(const Record& rec) {
  if (rec.size() >= 3 && !rec[2].text.empty()) return Expression::parse(rec[2]);
  if (rec.size() == 2 && !rec[1].text.empty()) return Expression::parse(rec[1]);
  throw DeckError(rec.fieldLoc(2), "LOOP needs a repeat count", rec.excerpt(rec.fieldLoc(2)),
                  "write LOOP,,n");
}

ParamBlock DeckParser::parseParams() {
  const Record head = next();
  std::vector<Record> body;
  while (true) {
    if (atEnd())
      throw DeckError(head[0].loc, "PARAmeter block is not ended by a blank record (end of file)",
                      head.excerpt(head[0].loc), "end the block with a blank record");
    const Record& r = peek();
    if (r.blank()) {
      ++pos_;
      break;
    }
    if (!hasEquals(r) && (isStructural(r) || isParamHead(r) || mesh_.find(r[0].text)))
      throw DeckError(r[0].loc,
                      "PARAmeter block (" + where(head) + ") is not ended by a blank record",
                      r.excerpt(r[0].loc), "insert a blank record before this one");
    body.push_back(next());
  }
  return parseParamBlock(head, body);
}

std::vector<TopItem> DeckParser::parseTopItems(const Record* loopHead) {
  std::vector<TopItem> items;
  while (true) {
    skipBlanks();
    if (atEnd()) {
      if (loopHead)
        throw DeckError((*loopHead)[0].loc, "LOOP without NEXT",
                        loopHead->excerpt((*loopHead)[0].loc), "close the loop with NEXT");
      return items;
    }
    const Record& r = peek();
    if (r.is("STOP")) {
      if (loopHead)
        throw DeckError(r[0].loc,
                        "STOP inside the LOOP of " + lineRef(*loopHead) + " (no NEXT before it)",
                        r.excerpt(r[0].loc), "close the loop with NEXT before STOP");
      return items;
    }
    if (r.is("NEXT")) {
      if (!loopHead) throw DeckError(r[0].loc, "NEXT without LOOP", r.excerpt(r[0].loc));
      return items;
    }
    if (r.is("LOOP")) {
      if (++loopDepth_ > DeckLimits::kMaxLoopDepth)
        throw DeckError(
            r[0].loc,
            "LOOP nested more than " + std::to_string(DeckLimits::kMaxLoopDepth) + " deep",
            r.excerpt(r[0].loc));
      TopLoop loop;
      loop.head = next();
      loop.count = loopCount(loop.head);
      loop.body = parseTopItems(&loop.head);
      loop.next = next();  // parseTopItems stops only at NEXT inside a loop
      --loopDepth_;
      items.emplace_back(std::move(loop));
      continue;
    }
    if (isParamHead(r)) {
      items.emplace_back(parseParams());
      continue;
    }
    if (r.is("SWEEp")) {
      items.emplace_back(parseSweep());
      continue;
    }
    if (r.is("ENSEmble")) {
      items.emplace_back(parseEnsemble(false));
      continue;
    }
    if (r.is("FEAP")) {
      items.emplace_back(parseProblem());
      continue;
    }
    std::string hint;
    if (mesh_.find(r[0].text))
      hint = "mesh commands follow a FEAP title record and its control record";
    else if (r.is("BATCh"))
      hint = "BATCh follows the END of a problem's mesh input";
    else if (r.is("END"))
      hint = "this END closes nothing";
    else
      hint = "a problem starts with a record 'FEAP * * title'";
    throw DeckError(
        r[0].loc,
        "unexpected record '" + r[0].text +
            "': expected FEAP, PARAmeter, LOOP, NEXT, SWEEp, ENSEmble or STOP",
        r.excerpt(r[0].loc), hint);
  }
}

TopSweep DeckParser::parseSweep() {
  TopSweep sw;
  sw.head = next();
  const Field& at = sw.head[0];
  while (true) {
    if (atEnd())
      throw DeckError(at.loc, "SWEEp block is not ended by a blank record (end of file)",
                      sw.head.excerpt(at.loc), "end the block with a blank record");
    const Record& r = peek();
    if (r.blank()) {
      ++pos_;
      break;
    }
    if (!hasEquals(r) && (isStructural(r) || isParamHead(r) || mesh_.find(r[0].text)))
      throw DeckError(r[0].loc, "SWEEp block (" + where(sw.head) + ") is not ended by a blank record",
                      r.excerpt(r[0].loc), "insert a blank record before this one");
    addSweepRecord(sw, next(), hasEquals(r));
  }
  checkSweepVariables(sw);
  // The sweep applies to the next problem; PARAmeter blocks before it go with
  // it, and an ENSEmble between them runs each of its plans n times.
  parseStudyBody(sw.body, sw.head, "SWEEp");
  if (!sw.body.empty())
    if (const auto* e = std::get_if<TopEnsemble>(&sw.body.back())) checkDrawsNotSwept(*e, sw);
  return sw;
}

void DeckParser::parseStudyBody(std::vector<TopItem>& body, const Record& head, const char* what) {
  const Field& at = head[0];
  while (true) {
    skipBlanks();
    const bool ensemble = !atEnd() && peek().is("ENSEmble") && std::string(what) == "SWEEp";
    if (atEnd() || !(isParamHead(peek()) || peek().is("FEAP") || ensemble)) {
      const bool eof = atEnd();
      throw DeckError(eof ? at.loc : peek()[0].loc,
                      std::string(what) + " (" + where(head) +
                          ") must be followed by the problem it applies to" +
                          (eof ? std::string(" (end of file)") : ", found '" + peek()[0].text + "'"),
                      eof ? head.excerpt(at.loc) : peek().excerpt(peek()[0].loc),
                      std::string("a ") + (std::string(what) == "SWEEp" ? "sweep" : "ensemble") +
                          " applies to the next FEAP problem (PARAmeter blocks may stand "
                          "between them)");
    }
    if (isParamHead(peek())) {
      body.emplace_back(parseParams());
      continue;
    }
    if (ensemble) {
      body.emplace_back(parseEnsemble(true));
      return;
    }
    body.emplace_back(parseProblem());
    return;
  }
}

TopItem DeckParser::parseEnsemble(bool inSweep) {
  TopEnsemble e;
  e.head = next();
  const Record& h = e.head;
  readEnsembleHead(e);
  while (true) {
    if (atEnd())
      throw DeckError(h[0].loc, "ENSEmble block is not ended by a blank record (end of file)",
                      h.excerpt(h[0].loc), "end the block with a blank record");
    const Record& r = peek();
    if (r.blank()) {
      ++pos_;
      break;
    }
    if (!hasEquals(r) && (isStructural(r) || isParamHead(r) || mesh_.find(r[0].text)))
      throw DeckError(r[0].loc, "ENSEmble block (" + where(h) + ") is not ended by a blank record",
                      r.excerpt(r[0].loc), "insert a blank record before this one");
    addEnsembleRecord(e, next(), hasEquals(r));
  }
  skipBlanks();
  if (!inSweep && !atEnd() && peek().is("SWEEp")) {
    // ENSEmble, then SWEEp: the same as the ensemble inside the sweep.
    TopSweep sw = parseSweep();
    for (const TopItem& item : sw.body)
      if (std::holds_alternative<TopEnsemble>(item))
        throw DeckError(std::get<TopEnsemble>(item).head[0].loc,
                        "a second ENSEmble for the same problem (the first at " + where(h) + ")",
                        std::get<TopEnsemble>(item).head.excerpt(std::get<TopEnsemble>(item).head[0].loc));
    e.body = std::move(sw.body);
    sw.body.clear();
    checkDrawsNotSwept(e, sw);
    sw.body.emplace_back(std::move(e));
    return sw;
  }
  parseStudyBody(e.body, h, "ENSEmble");
  return e;
}

Problem DeckParser::parseProblem() {
  Problem p;
  p.head = next();
  p.title = p.head.restOfLine(1);
  if (atEnd())
    throw DeckError(p.head[0].loc, "FEAP record without control record",
                    p.head.excerpt(p.head[0].loc),
                    "the next record is: numnp numel nummat ndm ndf nen");
  if (!peek().blank() && isControlKeyword(peek()[0].text)) {
    // FEAP's keyword form: 'keyword value' pairs up to a blank record.
    while (true) {
      if (atEnd())
        throw DeckError(p.head[0].loc,
                        "the keyword form of the control record is not ended by a blank record",
                        p.head.excerpt(p.head[0].loc), "end it with a blank record");
      const Record& r = next();
      if (r.blank()) break;
      for (std::size_t i = 0; i < r.size(); i += 2) {
        if (!isControlKeyword(r[i].text))
          throw DeckError(r[i].loc,
                          "unknown control keyword '" + r[i].text +
                              "' (a blank record ends the keyword form of the control record)",
                          r.excerpt(r[i].loc),
                          "the keywords are NODEs, ELEMents, MATErial, DIMEnsion, DOFS, "
                          "ELNOdes (or NUMNp, NUMEl, NUMMat, NDM, NDF, NEN)");
        if (i + 1 >= r.size() || r[i + 1].text.empty())
          throw DeckError(r.fieldLoc(i + 1), "control keyword '" + r[i].text + "' has no value",
                          r.excerpt(r.fieldLoc(i + 1)), "write " + r[i].text + "=n");
        Expression::parse(r[i + 1]);
      }
      p.controlKeywords.push_back(r);
    }
    parseMesh(p);
    parseBatches(p);
    return p;
  }
  p.control = next();
  if (!p.control.blank()) {
    const std::string& w = p.control[0].text;
    if (!looksNumeric(w) && (isStructural(p.control) || mesh_.find(w)))
      throw DeckError(
          p.control[0].loc, "missing control record after the FEAP title record",
          p.control.excerpt(p.control[0].loc),
          "insert 'numnp numel nummat ndm ndf nen' (e.g. 0 0 0 2 3 2) before this record");
    for (const auto& f : p.control.fields) Expression::parse(f);
  }
  parseMesh(p);
  parseBatches(p);
  return p;
}

void DeckParser::parseBatches(Problem& p) {
  while (true) {
    skipBlanks();
    if (atEnd()) break;
    const Record& r = peek();
    if (r.is("BATCh")) {
      p.batches.push_back(parseBatch());
      continue;
    }
    if (r.is("FEAP") || r.is("STOP") || r.is("LOOP") || r.is("NEXT") || r.is("SWEEp") ||
        r.is("ENSEmble") || isParamHead(r))
      break;
    throw DeckError(r[0].loc,
                    "expected BATCh after the END of the mesh input, found '" + r[0].text + "'",
                    r.excerpt(r[0].loc), r.is("END") ? "this END closes nothing" : std::string());
  }
}

void DeckParser::parseMesh(Problem& p) {
  if (!parseMeshItems(p.mesh, &p.meshEnd, &p.head))
    throw DeckError(p.head[0].loc, "the mesh input of this problem has no END",
                    p.head.excerpt(p.head[0].loc), "end the mesh commands with END");
}

std::vector<MeshItem> DeckParser::parseMeshInput() {
  std::vector<MeshItem> items;
  Record end;
  if (parseMeshItems(items, &end, nullptr)) {
    skipBlanks();
    if (!atEnd())
      throw DeckError(peek()[0].loc, "record after the END of the mesh input",
                      peek().excerpt(peek()[0].loc));
  }
  return items;
}

bool DeckParser::parseMeshItems(std::vector<MeshItem>& items, Record* end, const Record* head) {
  const Record* lastBlank = nullptr;
  const Record* lastCommand = nullptr;
  while (true) {
    if (atEnd()) return false;
    const Record& r = peek();
    if (r.blank()) {
      lastBlank = &r;
      ++pos_;
      continue;
    }
    if (r.is("END")) {
      *end = next();
      return true;
    }
    if (isParamHead(r)) {
      items.emplace_back(parseParams());
      lastCommand = nullptr;
      continue;
    }
    if (r.is("BATCh") || r.is("FEAP") || r.is("STOP"))
      throw DeckError(r[0].loc, "missing END of the mesh input before '" + r[0].text + "'",
                      r.excerpt(r[0].loc), "end the mesh commands with END");
    if (r.is("ENSEmble") || r.is("SWEEp"))
      throw DeckError(r[0].loc,
                      r[0].text + " inside the mesh input" +
                          (head ? " of the problem of " + lineRef(*head) : std::string()) +
                          ": a study block stands at the top level, before the FEAP record of "
                          "the problem it applies to",
                      r.excerpt(r[0].loc),
                      "move the block (up to its blank record) before the FEAP record");
    const CommandSpec* spec = mesh_.find(r[0].text);
    if (!spec) {
      if (looksNumeric(r[0].text)) {
        std::string hint = "data records follow their command";
        if (lastCommand && lastBlank && lastBlank->loc.line > lastCommand->loc.line)
          hint = "the blank record at " + where(*lastBlank) + " ended the data set of '" +
                 (*lastCommand)[0].text + "' (" + where(*lastCommand) + ")";
        throw DeckError(r[0].loc, "data record outside a data set, expected a mesh command",
                        r.excerpt(r[0].loc), hint);
      }
      std::string hint = mesh_.suggest(r[0].text);
      throw DeckError(r[0].loc, "unknown mesh command '" + r[0].text + "'", r.excerpt(r[0].loc),
                      hint.empty() ? "see collapse2d --help for the mesh commands" : hint);
    }
    lastCommand = &r;
    items.emplace_back(parseMeshCommand(*spec));
  }
}

bool DeckParser::startsItem(const Record& r) const {
  if (r.blank()) return false;
  if (isStructural(r) || isParamHead(r)) return true;
  return Parameters::validName(r[0].text) && !hasEquals(r) && mesh_.find(r[0].text);
}

void DeckParser::checkDataRecord(const Record& rec, const Record& head,
                                 const CommandSpec& spec) const {
  const std::string& w = rec[0].text;
  const bool material = spec.key() == "mate";
  bool command = false;
  if (Parameters::validName(w) && !hasEquals(rec)) {
    if (isStructural(rec) || isParamHead(rec))
      command = true;
    else if (mesh_.find(w))
      command = !(material && sub_.find(w));
  }
  if (command)
    throw DeckError(rec[0].loc,
                    "the data set of '" + head[0].text + "' (" + where(head) +
                        ") is not ended by a blank record",
                    rec.excerpt(rec[0].loc), "insert a blank record before this one");
  // Syntax check now; text fields (CARTesian, GROUnd, ISOTropic) are plain names.
  for (const auto& f : rec.fields) Expression::parse(f);
}

MeshCommand DeckParser::parseMeshCommand(const CommandSpec& spec) {
  MeshCommand c;
  c.head = next();
  for (std::size_t i = 1; i < c.head.size() && i <= spec.fields.size(); ++i)
    if (spec.fields[i - 1].kind != FieldKind::Text) Expression::parse(c.head[i]);
  if (spec.data == DataForm::None) return c;
  if (spec.data == DataForm::Single) {
    // FEAP reads the next record (SHIFt); values on the command record need none.
    bool inline_ = false;
    for (std::size_t i = 1; i < c.head.size(); ++i) inline_ = inline_ || !c.head[i].text.empty();
    if (inline_) return c;
    if (atEnd())
      throw DeckError(c.head[0].loc,
                      "'" + c.head[0].text + "' needs its data record: " + spec.dataSyntax,
                      c.head.excerpt(c.head[0].loc));
    if (!peek().blank()) checkDataRecord(peek(), c.head, spec);
    c.data.push_back(next());
    return c;
  }
  // Optional records (SITE): a command, END or a parameter block right after
  // the command record means it has none, as decks wrote it before it had any.
  if (spec.data == DataForm::Optional && (atEnd() || startsItem(peek()))) return c;
  while (true) {
    if (atEnd())
      throw DeckError(
          c.head[0].loc,
          "the data set of '" + c.head[0].text + "' is not ended by a blank record (end of file)",
          c.head.excerpt(c.head[0].loc), "end the data records with a blank record");
    const Record& r = peek();
    if (r.blank()) {
      ++pos_;
      break;
    }
    checkDataRecord(r, c.head, spec);
    c.data.push_back(next());
  }
  return c;
}

bool DeckParser::topLevelParamsAhead() const {
  std::size_t p = pos_;
  while (p < records_.size() && isParamHead(records_[p])) {
    ++p;
    while (p < records_.size() && !records_[p].blank()) ++p;
    if (p >= records_.size()) return false;
    while (p < records_.size() && records_[p].blank()) ++p;
  }
  // A parameter block belongs to the top level when the next item is a problem, a
  // loop, the end of a loop or of the input.
  return p >= records_.size() || records_[p].is("FEAP") || records_[p].is("LOOP") ||
         records_[p].is("NEXT") || records_[p].is("STOP") || records_[p].is("SWEEp") ||
         records_[p].is("ENSEmble");
}

bool DeckParser::endsBatchData() const {
  const Record& r = peek();
  if (r.blank()) return false;
  if (r.is("BATCh") || r.is("FEAP") || r.is("STOP") || r.is("LOOP") || r.is("NEXT") ||
      r.is("SWEEp") || r.is("ENSEmble"))
    return true;
  return isParamHead(r) && topLevelParamsAhead();
}

BatchBlock DeckParser::parseBatch() {
  BatchBlock b;
  b.head = next();
  while (true) {
    if (atEnd())
      throw DeckError(b.head[0].loc, "BATCh block without END", b.head.excerpt(b.head[0].loc),
                      "end the solution commands with END");
    const Record& r = peek();
    if (r.blank()) {
      ++pos_;
      continue;
    }
    if (r.is("END")) {
      b.end = next();
      break;
    }
    if (r.is("BATCh") || r.is("FEAP") || r.is("STOP"))
      throw DeckError(
          r[0].loc,
          "the BATCh block of " + where(b.head) + " has no END before '" + r[0].text + "'",
          r.excerpt(r[0].loc), "end the solution commands with END");
    b.commands.push_back(next());
  }
  while (!atEnd() && !endsBatchData()) b.data.push_back(next());
  return b;
}

}  // namespace c2d
