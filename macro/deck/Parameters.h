#pragma once
// The parameter table of a run: case-insensitive names to values. PARAmeter
// blocks fill it in deck order; expressions read it when they are evaluated.
// Each name keeps where it was last set (the record of its assignment or
// sweep), so that an error about a value a parameter gave can say where.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/Error.h"

namespace c2d {

struct Field;

class Parameters {
 public:
  // where: the assignment's location (none: an empty file name).
  void set(std::string_view name, double value, const SourceLoc& where = {});
  // set() for a name a deck record assigns (PARAmeter blocks, PARA): a name a
  // study sets for each run is a DeckError at `at`, which the deck may not
  // change (every plan would run with the new value while the tables, file
  // names and log show the study's).
  void assign(std::string_view name, double value, const Field& at);
  // Names a study sets for each run (SWEEp, ENSEmble): `by` says how
  // ("swept by the SWEEp of line 3"). unprotect() when the study's runs end.
  void protect(std::string_view name, std::string by);
  void unprotect(std::string_view name);
  const std::string* protectedBy(std::string_view name) const;
  bool has(std::string_view name) const;
  // The value of a defined name; std::out_of_range when it is not defined.
  double get(std::string_view name) const;
  std::optional<double> find(std::string_view name) const;
  // Where a defined name was last set; nullopt when unknown or not defined.
  std::optional<SourceLoc> origin(std::string_view name) const;
  // Values given from outside the deck (--set NAME=VALUE, collapse2d.run's
  // params), keys in lower case: an assignment of such a name by a deck record
  // (assign) takes the given value instead of its own, so that everything the
  // deck computes from it follows. Copies of this table share the record of
  // which names a record assigned (overridesUnused).
  void setOverrides(const std::map<std::string, double>& values);
  bool overridden(std::string_view name) const;
  // The given names no deck record assigned so far (lower case, sorted).
  std::vector<std::string> overridesUnused() const;
  // Defined names (lower case, sorted), e.g. for "did you mean" hints.
  std::vector<std::string> names() const;
  std::size_t size() const { return values_.size(); }
  void clear() {
    values_.clear();
    origins_.clear();
  }

  // A valid name: a letter or '_', then letters, digits or '_'.
  static bool validName(std::string_view name);

 private:
  std::map<std::string, double> values_;      // keys in lower case
  std::map<std::string, SourceLoc> origins_;  // of the names set with a location
  std::map<std::string, std::string> protected_;  // keys in lower case
  struct Overrides {
    std::map<std::string, double> values;  // keys in lower case
    std::map<std::string, bool> assigned;   // by a deck record
  };
  std::shared_ptr<Overrides> overrides_;  // shared by the copies of the table
};

}  // namespace c2d
