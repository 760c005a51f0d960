#pragma once
// The first phase: lines to records. Comments ('!' to the end of the line) are
// dropped, fields split, and INCLude records replaced by the records of the
// included file, so that later phases see one flat stream in which every record
// keeps its own file and line.
#include <string>
#include <string_view>
#include <vector>

#include "macro/deck/Record.h"

namespace c2d {

class DeckReader {
 public:
  static constexpr int kMaxRecordLength = 256;
  static constexpr int kMaxIncludeDepth = 32;

  // Reads a deck file and, recursively, every file it includes.
  // A file that cannot be opened is a DeckError (at the INCLude record for an include).
  static std::vector<Record> readFile(const std::string& path);

  // The same for deck text in memory; name is used in locations, and INCLude
  // paths are relative to baseDir.
  static std::vector<Record> readString(const std::string& text, const std::string& name,
                                        const std::string& baseDir = ".");

  // Splits one line (without its line end) into a record; no INCLude processing.
  static Record lexLine(std::string_view line, const std::string& file, int lineNo);

 private:
  static void readText(const std::string& text, const std::string& name, const std::string& baseDir,
                       std::vector<std::string>& openFiles, std::vector<Record>& out);
  static void include(const Record& rec, const std::string& baseDir,
                      std::vector<std::string>& openFiles, std::vector<Record>& out);
};

}  // namespace c2d
