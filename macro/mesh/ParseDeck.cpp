#include "macro/mesh/ParseDeck.h"

#include <utility>

#include "macro/deck/DeckParser.h"
#include "macro/deck/DeckReader.h"
#include "macro/mesh/MeshCommands.h"

namespace c2d {

namespace {

Deck parseRecords(std::vector<Record> records, const std::string& path) {
  CommandRegistry mesh("Mesh commands");
  registerMeshCommands(mesh);
  CommandRegistry sub("Material records");
  registerMaterialSubRecords(sub);
  return DeckParser(std::move(records), path, mesh, sub).parse();
}

}  // namespace

Deck parseDeck(const std::string& path) { return parseRecords(DeckReader::readFile(path), path); }

std::vector<MeshItem> parseMeshRecords(std::vector<Record> records, const std::string& path) {
  CommandRegistry mesh("Mesh commands");
  registerMeshCommands(mesh);
  CommandRegistry sub("Material records");
  registerMaterialSubRecords(sub);
  return DeckParser(std::move(records), path, mesh, sub).parseMeshInput();
}

Deck parseDeckText(const std::string& text, const std::string& name, const std::string& baseDir) {
  return parseRecords(DeckReader::readString(text, name, baseDir), name);
}

}  // namespace c2d
