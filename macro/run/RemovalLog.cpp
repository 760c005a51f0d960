#include "macro/run/RemovalLog.h"
#include "macro/output/NumberText.h"

#include <cstdio>
#include <vector>

namespace c2d {

namespace {

// 0-based numbers as the deck's, ranges of consecutive ones joined: "3, 5-7".
std::string numberList(const std::vector<int>& numbers) {
  std::string out;
  for (std::size_t i = 0; i < numbers.size();) {
    std::size_t j = i;
    while (j + 1 < numbers.size() && numbers[j + 1] == numbers[j] + 1) ++j;
    if (!out.empty()) out += ", ";
    out += std::to_string(numbers[i] + 1);
    if (j > i) out += (j == i + 1 ? ", " : "-") + std::to_string(numbers[j] + 1);
    i = j + 1;
  }
  return out;
}

// "element 3" / "elements 3-5"
std::string elements(const std::vector<int>& list) {
  return std::string(list.size() == 1 ? "element " : "elements ") + numberList(list);
}

}  // namespace

RemovalLog removalLog(const RemovalEvent& ev) {
  RemovalLog out;
  const std::string when = " at t = " + formatNumber("%.6e", ev.time);
  // The record that gave the blast, when known: "(BLASt record f.inp:12:3)".
  const std::string record =
      ev.origin.file.empty() ? std::string() : " (BLASt record " + ev.origin.str() + ")";
  if (ev.elements.empty()) {
    out.warning = true;
    out.text = "  warning: the blast" + when + record + " removes nothing: its " +
               elements(ev.goneBefore) + (ev.goneBefore.size() == 1 ? " was" : " were") +
               " removed before by REMOve\n";
    return out;
  }
  std::string& s = out.text;
  s = "  " + std::string(ev.scheduled ? "blast " : "remove") + when + ": " + elements(ev.elements) +
      " removed, ";
  s += ev.release > 0 ? "forces released over td = " + formatNumber("%.4e", ev.release)
                      : "at once";
  if (!ev.nodesLeaving.empty())
    s += std::string("; node") + (ev.nodesLeaving.size() == 1 ? " " : "s ") +
         numberList(ev.nodesLeaving) + " leave" + (ev.nodesLeaving.size() == 1 ? "s" : "") +
         " the model";
  if (ev.jointsDissolved > 0)
    s += "; " + std::to_string(ev.jointsDissolved) + " joint" +
         (ev.jointsDissolved == 1 ? "" : "s") + " dissolved";
  if (!ev.goneBefore.empty()) s += "; " + elements(ev.goneBefore) + " removed before" + record;
  s += "; energy removed " + formatNumber("%.6e", ev.energy) + "\n";
  return out;
}

}  // namespace c2d
