#pragma once
// A log line that repeats for the same reason (a joint held past thetaR in
// every step of a long fall: thousands of lines) is written for its first few
// cases only; the others are counted, and the run's end says how many lines of
// each reason were left out and how many cases (joints, elements) they were.
#include <cstddef>
#include <map>
#include <set>
#include <string>

namespace c2d {

class LogFolding {
 public:
  // shown: how many lines of each reason are written in full.
  explicit LogFolding(std::size_t shown = 3) : shown_(shown) {}
  // Whether the line of `reason` about `item` (a joint, an element: what tells
  // its cases apart) is written; counts it either way.
  bool admit(const std::string& reason, const std::string& item);
  // One line per reason whose lines were left out (each starting with two
  // blanks, ending with a line end), "" when none was.
  std::string summary() const;

 private:
  struct Reason {
    std::size_t lines = 0;
    std::set<std::string> items;
  };
  std::size_t shown_;
  std::map<std::string, Reason> reasons_;
};

}  // namespace c2d
