#include "macro/deck/DeckReader.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace c2d {

namespace {

bool isBlankChar(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }
bool isSeparator(char c) { return isBlankChar(c) || c == ',' || c == '='; }

// Why path cannot be read as a deck ("" when it can, or does not exist: opening
// it then says so): a directory, or a device that may never end (/dev/zero).
// Pipes are read (a deck may come through one).
std::string notAFile(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto st = fs::status(path, ec);
  if (ec || !fs::exists(st)) return {};
  if (fs::is_directory(st)) return "is a directory";
  if (fs::is_character_file(st) || fs::is_block_file(st) || fs::is_socket(st))
    return "is not a regular file";
  return {};
}

std::string slurp(std::ifstream& in) {
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

Record DeckReader::lexLine(std::string_view raw, const std::string& file, int lineNo) {
  Record rec;
  rec.loc = {file, lineNo, 1};

  std::string shown(raw);
  std::replace_if(shown.begin(), shown.end(), isBlankChar, ' ');

  if (static_cast<int>(raw.size()) > kMaxRecordLength) {
    rec.line = std::make_shared<const std::string>(shown.substr(0, kMaxRecordLength));
    throw DeckError({file, lineNo, kMaxRecordLength + 1},
                    "record longer than " + std::to_string(kMaxRecordLength) + " characters",
                    rec.lineText() + " ...",
                    "split the record or shorten its comment; many values: a range lo:step:hi, or "
                    "continuation records (a SWEEp's record without 'name =' goes on with the "
                    "values of the one before)");
  }

  const std::size_t end = std::min(raw.find('!'), raw.size());
  for (std::size_t i = 0; i < end; ++i) {
    const auto c = static_cast<unsigned char>(raw[i]);
    if (c < 0x20 && !isBlankChar(raw[i])) {
      rec.line = std::make_shared<const std::string>(shown.substr(0, end));
      throw DeckError({file, lineNo, static_cast<int>(i) + 1},
                      "unexpected control character (code " + std::to_string(c) + ")",
                      rec.excerpt(static_cast<int>(i) + 1));
    }
  }

  std::string kept = shown.substr(0, end);
  while (!kept.empty() && kept.back() == ' ') kept.pop_back();
  rec.line = std::make_shared<const std::string>(std::move(kept));

  std::size_t pos = 0;
  auto skipBlanks = [&] {
    while (pos < end && isBlankChar(raw[pos])) ++pos;
  };
  skipBlanks();
  while (pos < end) {
    const std::size_t start = pos;
    while (pos < end && !isSeparator(raw[pos])) ++pos;
    rec.fields.push_back({std::string(raw.substr(start, pos - start)),
                          {file, lineNo, static_cast<int>(start) + 1},
                          rec.line});
    skipBlanks();
    if (pos >= end) break;
    if (raw[pos] == ',' || raw[pos] == '=') {
      ++pos;  // blanks around a comma or '=' belong to it
      skipBlanks();
    }
  }
  return rec;
}

void DeckReader::include(const Record& rec, const std::string& baseDir,
                         std::vector<std::string>& openFiles, std::vector<Record>& out) {
  if (rec.size() < 2 || rec[1].text.empty())
    throw DeckError(rec.fieldLoc(1), "INCLude needs a file name", rec.excerpt(rec.fieldLoc(1)),
                    "write INCLude,file (relative to this file's directory)");
  if (static_cast<int>(openFiles.size()) >= kMaxIncludeDepth)
    throw DeckError(rec[1].loc, "INCLude nested deeper than " + std::to_string(kMaxIncludeDepth),
                    rec.excerpt(rec[1].loc));

  namespace fs = std::filesystem;
  fs::path p(rec[1].text);
  if (p.is_relative()) p = fs::path(baseDir) / p;
  p = p.lexically_normal();
  const std::string name = p.string();

  if (const std::string why = notAFile(p); !why.empty())
    throw DeckError(rec[1].loc, "included file '" + name + "' " + why, rec.excerpt(rec[1].loc));
  std::ifstream in(p, std::ios::binary);
  if (!in)
    throw DeckError(rec[1].loc, "cannot open included file '" + name + "'",
                    rec.excerpt(rec[1].loc));
  std::error_code ec;
  const std::string canonical = fs::weakly_canonical(p, ec).string();
  if (std::find(openFiles.begin(), openFiles.end(), canonical) != openFiles.end())
    throw DeckError(rec[1].loc, "file '" + name + "' includes itself", rec.excerpt(rec[1].loc));

  openFiles.push_back(canonical);
  readText(slurp(in), name, p.parent_path().string(), openFiles, out);
  openFiles.pop_back();
}

void DeckReader::readText(const std::string& text, const std::string& name,
                          const std::string& baseDir, std::vector<std::string>& openFiles,
                          std::vector<Record>& out) {
  // A UTF-8 byte-order mark (editors on Windows write one) is not part of the first record.
  std::size_t start = text.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;
  int lineNo = 0;
  while (start < text.size()) {
    std::size_t nl = text.find('\n', start);
    if (nl == std::string::npos) nl = text.size();
    std::string_view line(text.data() + start, nl - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    ++lineNo;
    Record rec = lexLine(line, name, lineNo);
    if (rec.is("INCLude"))
      include(rec, baseDir.empty() ? std::string(".") : baseDir, openFiles, out);
    else
      out.push_back(std::move(rec));
    start = nl + 1;
  }
}

std::vector<Record> DeckReader::readFile(const std::string& path) {
  if (const std::string why = notAFile(path); !why.empty())
    throw DeckError({path, 0, 0}, "deck '" + path + "' " + why);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw DeckError({path, 0, 0}, "cannot open deck file '" + path + "'");
  namespace fs = std::filesystem;
  std::vector<std::string> openFiles;
  std::error_code ec;
  openFiles.push_back(fs::weakly_canonical(fs::path(path), ec).string());
  std::vector<Record> out;
  readText(slurp(in), path, fs::path(path).parent_path().string(), openFiles, out);
  return out;
}

std::vector<Record> DeckReader::readString(const std::string& text, const std::string& name,
                                           const std::string& baseDir) {
  std::vector<std::string> openFiles;
  std::vector<Record> out;
  readText(text, name, baseDir, openFiles, out);
  return out;
}

}  // namespace c2d
