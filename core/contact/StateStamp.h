#pragma once
// The state a kept result was found for (the member contact's step starts and
// step outcomes, docs/design/member-contact.md): its vectors compared to the
// bit and its pair memory, copied where they differ, so that no caller has to
// say when the state changed.
#include <Eigen/Core>
#include <vector>

#include "core/State.h"

namespace c2d {

class StateStamp {
 public:
  // Whether the positions at t_n+1 (withTrial), the positions and rates at
  // t_n and the pair memory of s are those of the last call; they are noted.
  bool same(const State& s, bool withTrial);

 private:
  Eigen::VectorXd u_, un_, vn_, an_;
  std::vector<PairMemory> pairs_;
};

}  // namespace c2d
