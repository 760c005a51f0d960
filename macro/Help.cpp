#include "macro/Help.h"

#include "macro/MeshCommands.h"
#include "macro/Sweep.h"

namespace c2d {

namespace {

void printSpec(std::ostream& os, const CommandSpec& s) {
  os << "  " << s.name;
  for (const FieldSpec& f : s.fields) os << "," << f.name;
  os << "\n      " << s.doc << "\n";
  for (const FieldSpec& f : s.fields) {
    if (f.doc.empty()) continue;
    os << "        " << f.name << ": " << f.doc;
    if (!f.defaultValue.empty()) os << " (default " << f.defaultValue << ")";
    os << "\n";
  }
  if (s.data == DataForm::Records) os << "      data records: " << s.dataSyntax << "\n";
}

}  // namespace

void printAllHelp(std::ostream& os, const SolutionCommands& solution) {
  CommandRegistry mesh("Mesh commands"), sub("Material sets: element types and sub-records");
  registerMeshCommands(mesh);
  registerMaterialSubRecords(sub);
  CommandRegistry blocks("Top-level blocks (before a problem)");
  registerDeckBlocks(blocks);
  for (const CommandRegistry* r : {static_cast<const CommandRegistry*>(&mesh), static_cast<const CommandRegistry*>(&sub), static_cast<const CommandRegistry*>(&blocks), &solution.registry()}) {
    os << r->title() << "\n";
    for (const CommandSpec& s : r->specs()) printSpec(os, s);
    os << "\n";
  }
}

bool printCommandHelp(std::ostream& os, const SolutionCommands& solution, const std::string& word) {
  CommandRegistry mesh("Mesh commands"), sub("Material sets: element types and sub-records");
  registerMeshCommands(mesh);
  registerMaterialSubRecords(sub);
  CommandRegistry blocks("Top-level blocks (before a problem)");
  registerDeckBlocks(blocks);
  bool found = false;
  for (const CommandRegistry* r : {static_cast<const CommandRegistry*>(&mesh), static_cast<const CommandRegistry*>(&sub), static_cast<const CommandRegistry*>(&blocks), &solution.registry()}) {
    if (const CommandSpec* s = r->find(word)) {
      os << r->title() << ":\n";
      printSpec(os, *s);
      found = true;
    }
  }
  if (!found) {
    os << "no command '" << word << "'";
    for (const CommandRegistry* r : {static_cast<const CommandRegistry*>(&mesh), static_cast<const CommandRegistry*>(&sub), static_cast<const CommandRegistry*>(&blocks), &solution.registry()}) {
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
