#include "macro/run/RunSummary.h"

#include <algorithm>
#include <cstdio>

#include "core/Hinge.h"
#include "macro/run/EnergyWatch.h"

namespace c2d {

RunSummary& RunSummary::operator+=(const RunSummary& s) {
  steps += s.steps;
  iterations += s.iterations;
  factorizations += s.factorizations;
  cuts += s.cuts;
  hinges += s.hinges;
  energyError = std::max(energyError, s.energyError);
  if (s.energyGained > energyGained) {
    energyGained = s.energyGained;
    gainStep = s.gainStep;
    gainTime = s.gainTime;
  }
  seconds += s.seconds;
  dynamic = dynamic || s.dynamic;
  maxMomentRatio = std::max(maxMomentRatio, s.maxMomentRatio);
  jointsFormed += s.jointsFormed;
  jointsRuptured += s.jointsRuptured;
  fractures += s.fractures;
  shears += s.shears;
  removed += s.removed;
  crossings += s.crossings;
  folded += s.folded;
  sunk += s.sunk;
  memberContact = memberContact || s.memberContact;
  blastsNotMade += s.blastsNotMade;
  debrisRuns += s.debrisRuns;
  outsideRuns += s.outsideRuns;
  movingRuns += s.movingRuns;
  unintendedRuns += s.unintendedRuns;
  if (!s.verdict.empty()) verdict = s.verdict;
  kineticRatio = std::max(kineticRatio, s.kineticRatio);
  return *this;
}

std::string runSummaryText(const RunSummary& s) {
  char buf[256];
  // The counts say what they count, for SECTion hinges (joints as they open)
  // and hand-given laws (a hinge softens fully into a joint) alike.
  std::snprintf(buf, sizeof buf, "%d step%s, %d iteration%s, %d cut%s, %d hinge%s opened",
                s.steps, s.steps == 1 ? "" : "s", s.iterations, s.iterations == 1 ? "" : "s",
                s.cuts, s.cuts == 1 ? "" : "s", s.hinges, s.hinges == 1 ? "" : "s");
  std::string out = buf;
  if (s.jointsFormed || s.jointsRuptured) {
    std::snprintf(buf, sizeof buf,
                  ", %d softened fully into joint%s, %d member%s parted past the rotation capacity",
                  s.jointsFormed, s.jointsFormed == 1 ? "" : "s", s.jointsRuptured,
                  s.jointsRuptured == 1 ? "" : "s");
    out += buf;
  }
  if (s.fractures > 0)
    out += ", " + std::to_string(s.fractures) + " member" + (s.fractures == 1 ? "" : "s") +
           " parted by their bars";
  if (s.shears > 0)
    out += ", " + std::to_string(s.shears) + " member" + (s.shears == 1 ? "" : "s") +
           " parted in shear";
  if (s.removed > 0) out += ", " + std::to_string(s.removed) + " removed";
  if (s.outsideRuns > 0)
    out += s.debrisRuns == 1 ? std::string(", debris OUTSIDE the site")
                             : ", debris OUTSIDE the site in " + std::to_string(s.outsideRuns) +
                                   " of " + std::to_string(s.debrisRuns) + " runs";
  if (s.unintendedRuns > 0)
    out += s.debrisRuns == 1 ? ", fall NOT AS INTENDED (" + s.verdict + ")"
                             : ", fall NOT AS INTENDED in " + std::to_string(s.unintendedRuns) +
                                   " of " + std::to_string(s.debrisRuns) + " runs";
  if (s.movingRuns > 0)
    out += s.debrisRuns == 1 ? std::string(", debris STILL MOVING at the end")
                             : ", debris STILL MOVING at the end in " +
                                   std::to_string(s.movingRuns) + " of " +
                                   std::to_string(s.debrisRuns) + " runs";
  if (s.maxMomentRatio > 0) {
    std::snprintf(buf, sizeof buf, ", max |M|/Mu %.4f", s.maxMomentRatio);
    out += buf;
  }
  std::snprintf(buf, sizeof buf, ", energy error %.2e", s.energyError);
  out += buf;
  if (s.energyGained > kEnergyBalanceTolerance) {
    std::snprintf(buf, sizeof buf, ", energy gained %.2e", s.energyGained);
    out += buf;
  }
  std::snprintf(buf, sizeof buf, ", %.2f s", s.seconds);
  return out + buf;
}

std::vector<std::string> runWarnings(const RunSummary& s) {
  std::vector<std::string> out;
  char buf[256];
  if (s.energyError > kEnergyBalanceTolerance) {
    std::snprintf(buf, sizeof buf,
                  "warning: the energy balance changed by %.2e of the peak energy (more than "
                  "%.0e): a force does work the model does not account for, or the tolerance "
                  "is loose",
                  s.energyError, kEnergyBalanceTolerance);
    out.push_back(buf);
  }
  if (s.gainStep > 0) out.push_back("warning: " + energyGainText(s.energyGained, s.gainStep, s.gainTime));
  if (s.crossings > 0) {
    std::snprintf(buf, sizeof buf,
                  "warning: %d pair%s of members cross each other at the end (listed in the "
                  "log): they passed through each other; %s",
                  s.crossings, s.crossings == 1 ? "" : "s",
                  s.memberContact ? "the member contact was too soft for an impact, or the "
                                    "pieces of a ruptured joint slid through each other"
                                  : "CONTact MEMBers,,k keeps them apart");
    out.push_back(buf);
  }
  if (s.maxMomentRatio > 1 + kCapacityTolerance) {
    std::snprintf(buf, sizeof buf,
                  "warning: a member carried |M|/Mu = %.4f, past its capacity by more than "
                  "%.1f %% (the element and the time in the log)",
                  s.maxMomentRatio, 100 * kCapacityTolerance);
    out.push_back(buf);
  }
  if (s.folded > 0) {
    std::snprintf(buf, sizeof buf,
                  "warning: %d member%s bent through more than a quarter turn at the end "
                  "(listed in the log): no RC member does that whole",
                  s.folded, s.folded == 1 ? " is" : "s are");
    out.push_back(buf);
  }
  if (s.sunk > 0) {
    std::snprintf(buf, sizeof buf,
                  "warning: %s a node went deeper into the ground than half the section depth "
                  "of its members (the log's debris lines): the ground is too soft for the "
                  "impact (GROUnd's k)",
                  s.sunk == 1 ? "in this run" : (std::to_string(s.sunk) + " runs:").c_str());
    out.push_back(buf);
  }
  if (s.movingRuns > 0) {
    std::snprintf(buf, sizeof buf,
                  "warning: %s the debris was still moving at the end (kinetic energy %.2e of "
                  "its peak): its figures are not final; run longer, or end the run at rest "
                  "with TIME,REST",
                  s.movingRuns == 1 ? "in this run" : (std::to_string(s.movingRuns) + " runs:").c_str(),
                  s.kineticRatio);
    out.push_back(buf);
  }
  if (s.blastsNotMade > 0) {
    std::snprintf(buf, sizeof buf,
                  "warning: %d blast%s of the BLASt plan did not happen (listed in the log): "
                  "the run ended before %s time, or %s elements were removed before",
                  s.blastsNotMade, s.blastsNotMade == 1 ? "" : "s",
                  s.blastsNotMade == 1 ? "its" : "their", s.blastsNotMade == 1 ? "its" : "their");
    out.push_back(buf);
  }
  return out;
}

}  // namespace c2d
