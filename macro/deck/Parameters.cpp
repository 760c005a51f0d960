#include "macro/deck/Parameters.h"

#include <cctype>
#include <stdexcept>

#include "macro/deck/Record.h"

namespace c2d {

void Parameters::set(std::string_view name, double value, const SourceLoc& where) {
  const std::string key = toLower(name);
  values_[key] = value;
  if (where.file.empty())
    origins_.erase(key);
  else
    origins_[key] = where;
}

std::optional<SourceLoc> Parameters::origin(std::string_view name) const {
  auto it = origins_.find(toLower(name));
  if (it == origins_.end()) return std::nullopt;
  return it->second;
}

void Parameters::assign(std::string_view name, double value, const Field& at) {
  if (const std::string* by = protectedBy(name))
    throw DeckError(at.loc,
                    "'" + (at.text.empty() ? std::string(name) : at.text) + "' is " + *by +
                        ": a PARAmeter record may not set it again (every run would take this "
                        "value while the tables, file names and log show the study's)",
                    at.excerpt(), "give this value another name");
  if (overrides_) {
    const std::string key = toLower(name);
    if (const auto it = overrides_->values.find(key); it != overrides_->values.end()) {
      overrides_->assigned[key] = true;
      value = it->second;
    }
  }
  set(name, value, at.loc);
}

void Parameters::setOverrides(const std::map<std::string, double>& values) {
  overrides_.reset();
  if (values.empty()) return;
  overrides_ = std::make_shared<Overrides>();
  for (const auto& [name, v] : values) {
    overrides_->values[toLower(name)] = v;
    overrides_->assigned[toLower(name)] = false;
  }
}

bool Parameters::overridden(std::string_view name) const {
  return overrides_ && overrides_->values.count(toLower(name)) != 0;
}

std::vector<std::string> Parameters::overridesUnused() const {
  std::vector<std::string> out;
  if (overrides_)
    for (const auto& [name, used] : overrides_->assigned)
      if (!used) out.push_back(name);
  return out;
}

void Parameters::protect(std::string_view name, std::string by) {
  protected_[toLower(name)] = std::move(by);
}

void Parameters::unprotect(std::string_view name) { protected_.erase(toLower(name)); }

const std::string* Parameters::protectedBy(std::string_view name) const {
  const auto it = protected_.find(toLower(name));
  return it == protected_.end() ? nullptr : &it->second;
}

bool Parameters::has(std::string_view name) const { return values_.count(toLower(name)) != 0; }

double Parameters::get(std::string_view name) const {
  auto it = values_.find(toLower(name));
  if (it == values_.end())
    throw std::out_of_range("undefined parameter '" + std::string(name) + "'");
  return it->second;
}

std::optional<double> Parameters::find(std::string_view name) const {
  auto it = values_.find(toLower(name));
  if (it == values_.end()) return std::nullopt;
  return it->second;
}

std::vector<std::string> Parameters::names() const {
  std::vector<std::string> out;
  out.reserve(values_.size());
  for (const auto& [name, value] : values_) out.push_back(name);
  return out;
}

bool Parameters::validName(std::string_view name) {
  if (name.empty()) return false;
  const auto first = static_cast<unsigned char>(name[0]);
  if (!std::isalpha(first) && first != '_') return false;
  for (char ch : name) {
    const auto c = static_cast<unsigned char>(ch);
    if (!std::isalnum(c) && c != '_') return false;
  }
  return true;
}

}  // namespace c2d
