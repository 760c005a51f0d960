#pragma once
// The parameter table of a run: case-insensitive names to values. PARAmeter
// blocks fill it in deck order; expressions read it when they are evaluated.
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace c2d {

class Parameters {
 public:
  void set(std::string_view name, double value);
  bool has(std::string_view name) const;
  // The value of a defined name; std::out_of_range when it is not defined.
  double get(std::string_view name) const;
  std::optional<double> find(std::string_view name) const;
  // Defined names (lower case, sorted), e.g. for "did you mean" hints.
  std::vector<std::string> names() const;
  std::size_t size() const { return values_.size(); }
  void clear() { values_.clear(); }

  // A valid name: a letter or '_', then letters, digits or '_'.
  static bool validName(std::string_view name);

 private:
  std::map<std::string, double> values_;  // keys in lower case
};

}  // namespace c2d
