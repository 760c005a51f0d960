#pragma once
// The solution commands that print and write results (DISP, VELO, ACCE, REAC,
// STRE, TPLOt, PLOT, PVIEw: their list is outputCommands() of
// SolutionCommandKit.h), and the checks of the columns PLOT,CURVe reads.
#include <memory>
#include <string>
#include <vector>

#include "macro/deck/Macro.h"
#include "macro/deck/Parameters.h"
#include "macro/commands/SolutionCommand.h"

namespace c2d {

// The columns of a TPLOt command as its records name them (time and prop
// first), with the parameters given; the names TimeHistory writes.
std::vector<std::string> timeHistoryColumns(const Macro& tplot, const Parameters& params);

// Every PLOT,CURVe of the bound BATCh blocks names columns that a TPLOt of the
// same problem writes: a DeckError at the offending field otherwise. Run after
// binding, before computing.
void checkPlotColumns(const std::vector<std::vector<Macro>>& batches, const Parameters& params);

}  // namespace c2d
