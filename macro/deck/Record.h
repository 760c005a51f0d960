#pragma once
// Records and fields of a deck: one line is one record, its fields separated by
// blanks, commas or '='. Every field keeps where it came from, so that any later
// phase can point at the offending text. A record with no fields is a blank
// record: it ends data sets.
#include <algorithm>
#include <cctype>
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/Error.h"

namespace c2d {

struct Field {
  std::string text;  // as written (case kept); empty for an empty field ("a,,b")
  SourceLoc loc;     // file, line, 1-based column of the first character
  std::shared_ptr<const std::string> line = {};  // the whole record, for messages

  // The record with a caret under column col (default: this field), for a
  // DeckError's "offending text" (DeckError indents each line by four blanks).
  std::string excerpt(int col = 0) const {
    if (col <= 0) col = loc.col;
    std::string s = line ? *line : text;
    const int shift = line ? 1 : loc.col;  // column of s[0]
    if (col >= shift) s += "\n    " + std::string(static_cast<std::size_t>(col - shift), ' ') + "^";
    return s;
  }
};

// Lower-case copy (deck keywords and parameter names are case-insensitive).
inline std::string toLower(std::string_view s) {
  std::string r(s);
  std::transform(r.begin(), r.end(), r.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return r;
}

// The key a command is matched on: its first four characters, lower case
// (shorter names are their own key).
inline std::string commandKey(std::string_view name) {
  return toLower(name.substr(0, std::min<std::size_t>(4, name.size())));
}

// FEAP's rule: a word matches a command when their first four characters agree,
// case-insensitively; a command name shorter than four characters (DT, TOL, END)
// matches only the word itself, so that "ENDS" is not END.
inline bool keywordMatches(std::string_view word, std::string_view name) {
  if (name.size() < 4) return toLower(word) == toLower(name);
  if (word.size() < 4) return false;
  return commandKey(word) == commandKey(name);
}

struct Record {
  std::vector<Field> fields;
  SourceLoc loc;                            // column 1 of the line
  std::shared_ptr<const std::string> line;  // the line, comment removed, tabs shown as blanks

  bool blank() const { return fields.empty(); }
  std::size_t size() const { return fields.size(); }
  const Field& operator[](std::size_t i) const { return fields[i]; }
  // Text of field i, or "" when the record is shorter.
  std::string text(std::size_t i) const {
    return i < fields.size() ? fields[i].text : std::string();
  }
  // Location of field i, or just past the end of the record when it is shorter.
  SourceLoc fieldLoc(std::size_t i) const {
    if (i < fields.size()) return fields[i].loc;
    SourceLoc l = loc;
    l.col = line ? static_cast<int>(line->size()) + 1 : 1;
    return l;
  }
  // Does the first field name this command (four-character rule)?
  bool is(std::string_view name) const { return !blank() && keywordMatches(fields[0].text, name); }
  std::string lineText() const { return line ? *line : std::string(); }
  // The line from field i on, as written (a title, a material's label).
  std::string restOfLine(std::size_t i) const {
    if (i >= fields.size() || !line) return {};
    const auto p = static_cast<std::size_t>(fields[i].loc.col - 1);
    return p < line->size() ? line->substr(p) : std::string();
  }
  // The record with a caret under column col, for DeckError's "offending text"
  // (DeckError indents each line it prints by four blanks).
  std::string excerpt(int col) const {
    std::string s = lineText();
    if (col >= 1) s += "\n    " + std::string(static_cast<std::size_t>(col - 1), ' ') + "^";
    return s;
  }
  std::string excerpt(const SourceLoc& at) const { return excerpt(at.col); }
};

}  // namespace c2d
