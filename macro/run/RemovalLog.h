#pragma once
// The log's lines of a member removal (solvers/MemberRemoval.h): a blast at
// its time or a REMOve, the elements and nodes that left, the joints
// dissolved, the energy removed; a blast whose elements had all left before
// (REMOve) removes nothing and is a warning, at its BLASt record.
#include <string>

#include "solvers/MemberRemoval.h"

namespace c2d {

struct RemovalLog {
  std::string text;      // whole lines, each ending in '\n'
  bool warning = false;  // the blast removed nothing
};

RemovalLog removalLog(const RemovalEvent& ev);

}  // namespace c2d
