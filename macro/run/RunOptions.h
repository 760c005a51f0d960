#pragma once
// How a problem of a deck is run (ProblemRun): where its outputs go and under
// what name, its solver, the deck's warnings, the safe points, an ensemble's
// sample, the pictures.
#include <filesystem>
#include <functional>
#include <string>

#include "macro/deck/Warnings.h"

namespace c2d {

struct SampleDraws;  // macro/draws/Ensemble.h

struct RunOptions {
  std::filesystem::path outDir = ".";
  std::string stem = "run";  // base name of the output files of this run
  std::string label;         // what tells this run apart (sweep values) in titles and legends
  bool progress = false;     // a single updating progress line on stderr
  std::string solver = "auto";
  Warnings* warnings = nullptr;  // where bind() puts deck warnings (null: dropped)
  // Called at every safe point of the run (between two solution commands), e.g.
  // to check that the log is still being written.
  std::function<void()> safePoint;
  // A sample of an ENSEmble (macro/draws/Ensemble.h): its nodes jittered
  // before the elements are built, its time steps scaled, its blast times
  // scattered. Null outside an ensemble.
  const SampleDraws* sample = nullptr;
  // Pictures and ParaView files (PLOT, PVIEw) are written (an ensemble's
  // samples after the first write their tables only).
  bool pictures = true;
};

}  // namespace c2d
