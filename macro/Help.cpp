#include "macro/Help.h"

#include <array>
#include <string>

#include "macro/mesh/MeshCommands.h"
#include "macro/deck/Record.h"
#include "macro/deck/StudyBlocks.h"
#include "macro/mesh/Units.h"

namespace c2d {

namespace {

// Text filled to lines of at most 79 columns (a longer word gets a line of its
// own), the first line after `lead`, the others indented by `indent` blanks.
void printWrapped(std::ostream& os, const std::string& lead, std::size_t indent, const std::string& text) {
  constexpr std::size_t kWidth = 79;
  std::string line = lead;
  bool empty = lead.empty() || lead.back() == ' ';  // no blank needed before the next word
  std::size_t p = 0;
  while (p < text.size()) {
    const std::size_t b = text.find_first_not_of(' ', p);
    if (b == std::string::npos) break;
    std::size_t e = text.find(' ', b);
    if (e == std::string::npos) e = text.size();
    const std::string w = text.substr(b, e - b);
    if (!empty && line.size() + 1 + w.size() > kWidth) {
      os << line << "\n";
      line = std::string(indent, ' ');
      empty = true;
    }
    if (!empty) line += ' ';
    line += w;
    empty = false;
    p = e;
  }
  os << line << "\n";
}

void printSpec(std::ostream& os, const CommandSpec& s) {
  os << "  " << s.name;
  for (const FieldSpec& f : s.fields) os << "," << f.name;
  os << "\n";
  printWrapped(os, "      ", 6, s.doc);
  for (const FieldSpec& f : s.fields) {
    const auto unit = units::ofField(s.section, s.key(), f.name);
    if (f.doc.empty() && !(unit && !unit->empty())) continue;
    std::string doc = f.doc;
    // The unit in the decks' system (--help UNITs), unless the doc gives it.
    if (unit && !unit->empty() && doc.find('[') == std::string::npos) doc += " [" + *unit + "]";
    if (!f.defaultValue.empty()) doc += " (default " + f.defaultValue + ")";
    printWrapped(os, "        " + f.name + ":", 10, doc);
  }
  if (s.data == DataForm::Records) printWrapped(os, "      data records:", 8, s.dataSyntax);
  if (s.data == DataForm::Optional)
    printWrapped(os, "      data records (optional):", 8,
                 s.dataSyntax + "; a blank record ends them; none when a command follows at once");
  if (s.data == DataForm::Single)
    printWrapped(os, "      data record:", 8, s.dataSyntax + " (the next record)");
  if (const std::string u = units::ofDataRecords(s.section, s.key()); !u.empty())
    printWrapped(os, "      units:", 8, u);
}

// The deck's command registries, in the order help lists them.
struct DeckRegistries {
  CommandRegistry mesh{"Mesh commands"}, sub{"Material sets: element types and sub-records"},
      blocks{"Top-level blocks (before a problem)"};
  DeckRegistries() {
    registerMeshCommands(mesh);
    registerMaterialSubRecords(sub);
    registerDeckBlocks(blocks);
    registerEnsembleBlock(blocks);
  }
  std::array<const CommandRegistry*, 4> all(const SolutionCommands& solution) const {
    return {&mesh, &sub, &blocks, &solution.registry()};
  }
};

}  // namespace

void printAllHelp(std::ostream& os, const SolutionCommands& solution) {
  const DeckRegistries deck;
  for (const CommandRegistry* r : deck.all(solution)) {
    os << r->title() << "\n";
    for (const CommandSpec& s : r->specs()) printSpec(os, s);
    os << "\n";
  }
  printWrapped(os, "", 0, units::systemHelp() + " (collapse2d --help UNITs)");
}

bool printCommandHelp(std::ostream& os, const SolutionCommands& solution, const std::string& word) {
  if (keywordMatches(word, "UNITs")) {
    printWrapped(os, "", 0, units::systemHelp());
    return true;
  }
  const DeckRegistries deck;
  bool found = false;
  for (const CommandRegistry* r : deck.all(solution)) {
    if (const CommandSpec* s = r->find(word)) {
      os << r->title() << ":\n";
      printSpec(os, *s);
      found = true;
    }
  }
  if (!found) {
    os << "no command '" << word << "'";
    for (const CommandRegistry* r : deck.all(solution)) {
      const std::string hint = r->suggest(word);
      if (!hint.empty()) {
        os << "; " << hint;
        break;
      }
    }
    os << "\n";
  }
  return found;
}

}  // namespace c2d
