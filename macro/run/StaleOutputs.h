#pragma once
// The files an earlier run of the same stem left in the output directory that
// a new run would otherwise leave beside its own: what a failed or interrupted
// run kept under tagged names (<stem>.failed.out, <stem>_tplot.interrupted.csv,
// <stem>.interrupted.pvd, ...: core/io/AtomicFile.h tagged), its ParaView frames
// (<stem>_0000.vtu, ...) and its deformed shapes (<stem>_deformed_0042.svg).
// Frames and pictures are named by their number, so a rerun that writes fewer
// of them, or at other steps, would leave the old ones looking like its own.
// A run removes them before it writes anything; the other files of a stem
// (the log, the time history, the collection, the other pictures) the new run
// replaces by name.
#include <filesystem>
#include <string>

namespace c2d {

// Removes those files of `stem` in `dir`; a file that cannot be removed is
// left (the run's own outputs are written whatever). Returns how many were removed.
int removeStaleOutputs(const std::filesystem::path& dir, const std::string& stem);

}  // namespace c2d
