#pragma once
// Fields of a material sub-record ("two text fields, then numbers"): the
// checks and values shared by the sub-record binders (macro/mesh/MeshCommands,
// macro/mesh/SectionRecords).
#include <string>
#include <vector>

#include "macro/mesh/MeshCommands.h"

namespace c2d::subrecord {

// DeckError when the second field is a number: "NAME takes two text fields,
// then numbers", with the syntax as the hint.
void requireText(const Record& r, const std::string& name, const std::string& syntax);
// The numbers from field 2 on: at most maxCount, at least `required` (absent
// ones 0); DeckErrors "too many values" and "NAME needs n values".
std::vector<double> values(const MeshContext& ctx, const Record& r, const std::string& name,
                           std::size_t maxCount, std::size_t required, const std::string& syntax);
bool looksNumeric(const std::string& t);
// The first number field of a record of numbers only (REBAr d1 A1 ...,
// STIRrups Asw s): field 1, or 2 after an empty field ("STIRrups,,1e-4,0.2").
inline std::size_t firstNumber(const Record& r) {
  return r.size() > 1 && r.text(1).empty() ? 2 : 1;
}

}  // namespace c2d::subrecord
