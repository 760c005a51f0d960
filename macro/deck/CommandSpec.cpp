#include "macro/deck/CommandSpec.h"

#include <algorithm>
#include <ostream>
#include <stdexcept>

#include "macro/deck/Record.h"
#include "macro/deck/Suggest.h"

namespace c2d {

std::string CommandSpec::key() const { return commandKey(name); }

bool CommandSpec::matches(std::string_view word) const {
  if (keywordMatches(word, name)) return true;
  return std::any_of(aliases.begin(), aliases.end(),
                     [&](const std::string& a) { return keywordMatches(word, a); });
}

void CommandRegistry::add(CommandSpec spec) {
  if (spec.name.empty()) throw std::logic_error("command spec without a name");
  std::vector<std::string> names{spec.name};
  names.insert(names.end(), spec.aliases.begin(), spec.aliases.end());
  for (const auto& n : names) {
    for (const auto& other : specs_) {
      std::vector<std::string> otherNames{other.name};
      otherNames.insert(otherNames.end(), other.aliases.begin(), other.aliases.end());
      for (const auto& o : otherNames)
        if (commandKey(n) == commandKey(o))
          throw std::logic_error("command '" + n + "' matches the same four characters as '" + o +
                                 "'" + (title_.empty() ? "" : " in " + title_));
    }
  }
  specs_.push_back(std::move(spec));
}

const CommandSpec* CommandRegistry::find(std::string_view word) const {
  for (const auto& s : specs_)
    if (s.matches(word)) return &s;
  return nullptr;
}

std::string CommandRegistry::suggest(std::string_view word) const {
  if (word.empty()) return {};
  const std::string w = toLower(word);
  const std::string w4 = commandKey(w);
  const CommandSpec* best = nullptr;
  int bestScore = 1 << 20;
  for (const auto& s : specs_) {
    std::vector<std::string> names{s.name};
    names.insert(names.end(), s.aliases.begin(), s.aliases.end());
    for (const auto& n : names) {
      const int dKey = editDistance(w4, commandKey(n));
      const int dFull = editDistance(w, toLower(n));
      const bool close = dKey <= 1 || dFull <= std::max(1, static_cast<int>(w.size()) / 3);
      const int score = std::min(dKey, dFull);
      if (close && score < bestScore) {
        bestScore = score;
        best = &s;
      }
    }
  }
  return best ? "did you mean '" + best->name + "'?" : std::string();
}

namespace {

const char* kindName(FieldKind k) {
  switch (k) {
    case FieldKind::Text:
      return "text";
    case FieldKind::Number:
      return "number";
    case FieldKind::Expression:
      return "expression";
  }
  return "";
}

void printFields(std::ostream& os, const std::vector<FieldSpec>& fields, const char* indent) {
  for (const auto& f : fields) {
    os << indent << f.name << " (" << kindName(f.kind);
    if (!f.defaultValue.empty()) os << ", default " << f.defaultValue;
    os << ")";
    if (!f.doc.empty()) os << ": " << f.doc;
    os << "\n";
  }
}

}  // namespace

void CommandRegistry::printHelp(std::ostream& os) const {
  if (!title_.empty()) os << title_ << "\n\n";
  for (const auto& s : specs_) {
    os << "  " << s.name;
    for (const auto& f : s.fields) os << "," << f.name;
    for (const auto& a : s.aliases) os << "  (also " << a << ")";
    os << "\n      " << s.doc << "\n";
    printFields(os, s.fields, "        ");
    if (s.data == DataForm::Records) {
      os << "      data records: " << s.dataSyntax << "; a blank record ends them\n";
      printFields(os, s.dataFields, "        ");
    } else if (s.data == DataForm::Optional) {
      os << "      data records (optional): " << s.dataSyntax
         << "; a blank record ends them; none when a command follows at once\n";
      printFields(os, s.dataFields, "        ");
    } else if (s.data == DataForm::Single) {
      os << "      data record: " << s.dataSyntax << " (the next record)\n";
      printFields(os, s.dataFields, "        ");
    }
  }
}

}  // namespace c2d
