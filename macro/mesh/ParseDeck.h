#pragma once
// A deck parsed with the registries of the mesh commands and the material
// sub-records (macro/mesh/MeshCommands.h): DeckParser (macro/deck) takes them
// as given, these build them.
#include <string>
#include <vector>

#include "macro/deck/Deck.h"
#include "macro/deck/Record.h"

namespace c2d {

// Reads (INCLude expanded) and parses a deck file. Throws DeckError.
Deck parseDeck(const std::string& path);
// Mesh command records alone (MESH re-entry), END optional. Throws DeckError.
std::vector<MeshItem> parseMeshRecords(std::vector<Record> records, const std::string& path);
// The same for deck text in memory (tests, generated decks).
Deck parseDeckText(const std::string& text, const std::string& name = "<deck>",
                   const std::string& baseDir = ".");

}  // namespace c2d
