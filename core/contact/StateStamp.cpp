#include "core/contact/StateStamp.h"

#include <cstring>

namespace c2d {

namespace {

// Assigns b to a and tells whether they were the same already, to the bit
// (memcmp, not ==: the comparison runs at every assembly).
bool keep(Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  if (a.size() == b.size() &&
      (b.size() == 0 ||
       std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(b.size())) == 0))
    return true;
  a = b;
  return false;
}

}  // namespace

bool StateStamp::same(const State& s, bool withTrial) {
  // Every input compared (and copied when it differs).
  bool same = !withTrial || keep(u_, s.u);
  same = keep(un_, s.un) && same;
  same = keep(vn_, s.vn) && same;
  same = keep(an_, s.an) && same;
  if (same && pairs_ == s.pairs) return true;
  // With the room of the state's memory: steps allocate nothing while the
  // contacts change little.
  if (pairs_.capacity() < s.pairs.capacity()) pairs_.reserve(s.pairs.capacity());
  pairs_.assign(s.pairs.begin(), s.pairs.end());
  return false;
}

}  // namespace c2d
