#include "macro/mesh/SubRecordFields.h"

#include <cctype>

namespace c2d::subrecord {

bool looksNumeric(const std::string& t) {
  return !t.empty() && (std::isdigit(static_cast<unsigned char>(t[0])) || t[0] == '.' ||
                        t[0] == '-' || t[0] == '+' || t[0] == '(');
}

void requireText(const Record& r, const std::string& name, const std::string& syntax) {
  if (looksNumeric(r.text(1)))
    meshspec::failAt(r, 1, name + " takes two text fields, then numbers", "write " + syntax);
}

std::vector<double> values(const MeshContext& ctx, const Record& r, const std::string& name,
                           std::size_t maxCount, std::size_t required, const std::string& syntax) {
  if (r.size() > 2 + maxCount)
    meshspec::failAt(r, 2 + maxCount, "too many values: the record is '" + syntax + "'");
  if (r.size() < 2 + required)
    meshspec::failAt(r, r.size(), name + " needs " + std::to_string(required) + " values",
                     "write " + syntax);
  std::vector<double> v(maxCount, 0.0);
  for (std::size_t i = 0; i < maxCount; ++i) v[i] = ctx.number(r, 2 + i);
  return v;
}

}  // namespace c2d::subrecord
