// The solution commands' plumbing (deck language section 6): what their bind
// step reads (BindContext), the registry's lookup, and the binding of a BATCh
// block into a command tree (LOOP/NEXT matched). The registration list of the
// commands (each family's: ControlCommands, NewtonCommands, TimeCommands,
// OutputCommands, ModelCommands, RestartCommands) is
// macro/solution/SolutionCommands.cpp.
#include "macro/deck/DeckParser.h"
#include "macro/deck/Limits.h"
#include "macro/deck/SolutionCommand.h"

namespace c2d {

// ---------------------------------------------------------------- plumbing

const Record& BindContext::take(const Record& who, const char* what) {
  if (atEnd())
    throw DeckError(who.loc, std::string("missing ") + what + " after the BATCh END",
                    who.lineText());
  return data_[pos_++];
}

std::vector<Record> BindContext::takeSet(const Record& who, const char* what) {
  std::vector<Record> out;
  for (;;) {
    if (atEnd())
      throw DeckError(
          who.loc, std::string("the ") + what + " after the BATCh END must end with a blank record",
          who.lineText());
    const Record& rec = data_[pos_++];
    if (rec.blank()) break;
    out.push_back(rec);
  }
  return out;
}

void SolutionCommand::bind(Macro& m, BindContext& ctx) const {
  for (const Expression& e : m.numbers) e.eval(ctx.params());
}

bool Macro::newtonLoop() const {
  for (const Macro& b : body)
    if (b.is("tang") || b.is("utan") || b.is("solv")) return true;
  return false;
}

void SolutionCommands::add(std::unique_ptr<SolutionCommand> c) {
  registry_.add(c->spec());
  commands_.push_back(std::move(c));
}

const SolutionCommand* SolutionCommands::find(const std::string& word) const {
  const CommandSpec* s = registry_.find(word);
  if (!s) return nullptr;
  for (const auto& c : commands_)
    if (c->spec().key() == s->key()) return c.get();
  return nullptr;
}

namespace {

Macro makeMacro(const Record& rec, const SolutionCommands& table) {
  Macro m;
  m.record = rec;
  m.command = table.find(rec.text(0));
  if (!m.command) {
    const std::string hint = table.registry().suggest(rec.text(0));
    throw DeckError(rec[0].loc, "unknown solution command '" + rec.text(0) + "'",
                    rec.excerpt(rec[0].loc), hint);
  }
  m.key = m.command->spec().key();
  m.optionText = rec.text(1);
  m.option = toLower(m.optionText);
  // Written fields the command does not read are errors, not ignored: an
  // option word where it takes none ("-"), a value beyond its last field.
  const CommandSpec& spec = m.command->spec();
  auto syntax = [&spec] {
    std::string s = "the command is " + spec.name.substr(0, 4);
    for (std::size_t i = 0; i < spec.fields.size(); ++i)
      s += "," + (i == 0 && spec.fields[0].name == "-" ? std::string() : spec.fields[i].name);
    return s;
  };
  if (!m.optionText.empty() && !spec.fields.empty() && spec.fields[0].name == "-")
    throw DeckError(rec[1].loc,
                    spec.name.substr(0, 4) + " takes no option word, got '" + m.optionText + "'",
                    rec.excerpt(rec[1].loc), syntax());
  for (std::size_t i = std::max<std::size_t>(spec.fields.size() + 1, 2); i < rec.size(); ++i)
    if (!rec.text(i).empty())
      throw DeckError(rec[i].loc, "a field beyond the command's last one would be ignored",
                      rec.excerpt(rec[i].loc), syntax());
  for (std::size_t i = 2; i < rec.size(); ++i) m.numbers.push_back(Expression::parse(rec[i]));
  return m;
}

// Builds the command tree with LOOP/NEXT matched; returns at the NEXT closing `loop`.
// depth: loops around this list (bounded, so that the recursion here, in
// binding and in running stays shallow).
std::vector<Macro> buildTree(const std::vector<Record>& recs, std::size_t& pos,
                             const SolutionCommands& table, Macro* loop, int depth) {
  std::vector<Macro> out;
  while (pos < recs.size()) {
    const Record& rec = recs[pos++];
    if (rec.blank()) continue;
    Macro m = makeMacro(rec, table);
    if (m.is("next")) {
      if (!loop) throw DeckError(rec.loc, "NEXT without a matching LOOP", rec.lineText());
      if (!m.optionText.empty() && !loop->optionText.empty() && m.option != loop->option)
        throw DeckError(rec[1].loc,
                        "NEXT," + m.optionText + " closes LOOP," + loop->optionText + " (" +
                            loop->record.loc.str() + ")",
                        rec.excerpt(rec[1].loc));
      loop->next = rec;
      return out;
    }
    if (m.is("loop")) {
      if (depth >= DeckLimits::kMaxLoopDepth)
        throw DeckError(
            rec[0].loc,
            "LOOP nested more than " + std::to_string(DeckLimits::kMaxLoopDepth) + " deep",
            rec.excerpt(rec[0].loc));
      m.body = buildTree(recs, pos, table, &m, depth + 1);
      if (m.next.blank()) throw DeckError(rec.loc, "LOOP without a matching NEXT", rec.lineText());
    }
    out.push_back(std::move(m));
  }
  return out;
}

void bindTree(std::vector<Macro>& list, BindContext& ctx) {
  for (Macro& m : list) {
    m.command->bind(m, ctx);
    if (m.is("loop")) bindTree(m.body, ctx);
  }
}

}  // namespace

std::vector<Macro> bindBatch(const std::vector<Record>& commands, const std::vector<Record>& data,
                             const SolutionCommands& table, Parameters& params, BindFacts* facts) {
  std::size_t pos = 0;
  std::vector<Macro> tree = buildTree(commands, pos, table, nullptr, 0);
  BindContext ctx(data, params, facts);
  bindTree(tree, ctx);
  while (!ctx.atEnd()) {
    const Record& rec = ctx.peek();
    if (!rec.blank())
      throw DeckError(rec.loc, "data record not read by any solution command", rec.lineText());
    ctx.skipBlank();
  }
  return tree;
}

}  // namespace c2d
