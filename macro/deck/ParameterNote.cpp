#include "macro/deck/ParameterNote.h"

#include <cctype>
#include <set>
#include <sstream>

#include "macro/deck/Record.h"

namespace c2d {

namespace {

bool nameStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool namePart(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

}  // namespace

DeckError noteParameters(const DeckError& e, const Parameters& params) {
  // The field at the error's column on the record's line (the first line of
  // the offending text); fields are separated by blanks, commas or '='.
  const std::string line = e.text().substr(0, e.text().find('\n'));
  const std::size_t start = static_cast<std::size_t>(e.loc().col - 1);
  if (e.loc().col < 1 || start >= line.size()) return e;
  std::size_t end = start;
  while (end < line.size() && line[end] != ' ' && line[end] != ',' && line[end] != '=' &&
         line[end] != '\t')
    ++end;
  const std::string field = line.substr(start, end - start);
  std::ostringstream note;
  std::set<std::string> seen;
  for (std::size_t i = 0; i < field.size();) {
    if (!nameStart(field[i])) {
      // A number's exponent (1e5, 1.0d-3) is no name.
      const bool number = std::isdigit(static_cast<unsigned char>(field[i])) || field[i] == '.';
      ++i;
      if (number)
        while (i < field.size() && (namePart(field[i]) || field[i] == '.')) ++i;
      continue;
    }
    std::size_t j = i;
    while (j < field.size() && namePart(field[j])) ++j;
    const std::string name = field.substr(i, j - i);
    i = j;
    if (i < field.size() && field[i] == '(') continue;  // a function
    const std::optional<double> value = params.find(name);
    if (!value || !seen.insert(toLower(name)).second) continue;
    note << (note.tellp() > 0 ? "; " : "") << name << " = " << *value;
    if (const auto at = params.origin(name))
      note << ", set "
           << (at->file == e.loc().file ? "on line " + std::to_string(at->line)
                                        : "at " + at->str());
  }
  if (note.tellp() <= 0) return e;
  return DeckError(e.loc(), e.message() + " (" + note.str() + ")", e.text(), e.hint());
}

}  // namespace c2d
