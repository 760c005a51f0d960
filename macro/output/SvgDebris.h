#pragma once
// PLOT,DEBRis: the debris picture as standalone SVG 1.1. Top: the frame in
// its current state (straight chords, one model length unit the same number of
// pixels in x and y), the ground line, the footprint (the x-extent of the
// nodes at the start, a gray band) and the site limits (red dashed lines).
// Below, on the same x axis: the mass lying along the ground as a histogram
// (macro/output/Debris.h massHistogram). The title carries the debris figures.
#include <filesystem>
#include <string>

#include "macro/output/Debris.h"
#include "core/Model.h"
#include "core/State.h"

namespace c2d {

// bins: number of histogram bins over the drawn x range.
std::string debrisSvg(const Model& model, const State& state, const DebrisFigures& figures,
                      const std::string& title, int bins = 40);
void saveDebrisSvg(const std::filesystem::path& path, const Model& model, const State& state,
                   const DebrisFigures& figures, const std::string& title);

}  // namespace c2d
