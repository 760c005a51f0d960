#pragma once
// Declared specs of deck commands and the registry they live in. A spec names
// the command as the manual writes it, with its four significant letters in
// upper case ("COORdinates"), says what it does and which fields it takes. The
// registry drives command lookup (four-character rule), "did you mean" hints
// and the generated --help. Registration lists are explicit functions; every
// registry is built by its user and passed by reference.
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

namespace c2d {

enum class FieldKind { Text, Number, Expression };
enum class CommandSection { Mesh, SubRecord, Solution };
enum class DataForm {
  None,     // the command record is all there is
  Records,  // data records follow, ended by a blank record
  Single,   // one data record follows (FEAP's SHIFt), unless the values stand on the command
  Optional, // data records ended by a blank record, none when a command follows at once
};

struct FieldSpec {
  std::string name;
  FieldKind kind = FieldKind::Expression;
  std::string defaultValue;  // shown in help; empty: none (an empty numeric field is 0)
  std::string doc;
};

struct CommandSpec {
  std::string name;  // "COORdinates": the upper-case prefix is what must be typed
  std::string doc;
  std::vector<FieldSpec> fields;  // fields of the command record after the name
  CommandSection section = CommandSection::Mesh;
  DataForm data = DataForm::None;
  std::string dataSyntax;             // one data record, e.g. "node ng x y"
  std::vector<FieldSpec> dataFields;  // its fields
  std::vector<std::string> aliases;   // synonyms (PARAmeter: CONStant)

  std::string key() const;  // first four characters, lower case
  bool matches(std::string_view word) const;
};

class CommandRegistry {
 public:
  explicit CommandRegistry(std::string title = {}) : title_(std::move(title)) {}

  // Throws std::logic_error when the spec (or one of its aliases) would match the
  // same four characters as a command already registered.
  void add(CommandSpec spec);
  const CommandSpec* find(std::string_view word) const;
  // "did you mean 'COORdinates'?" for the nearest command (edit distance on the
  // four-character key and on the full name), or "".
  std::string suggest(std::string_view word) const;
  const std::vector<CommandSpec>& specs() const { return specs_; }
  const std::string& title() const { return title_; }
  void printHelp(std::ostream& os) const;

 private:
  std::string title_;
  std::vector<CommandSpec> specs_;
};

}  // namespace c2d
