#pragma once
// The solution commands that write pictures and ParaView files (PLOT, PVIEw),
// registered in the SolutionCommands list like every other command.
#include <memory>
#include <string>
#include <vector>

#include "macro/Macro.h"
#include "macro/Parameters.h"
#include "macro/SolutionCommand.h"

namespace c2d {

std::unique_ptr<SolutionCommand> makePlotCommand();
std::unique_ptr<SolutionCommand> makeParaViewCommand();

// The columns of a TPLOt command as its records name them (time and prop
// first), with the parameters given; the names TimeHistory writes.
std::vector<std::string> timeHistoryColumns(const Macro& tplot, const Parameters& params);

// Every PLOT,CURVe of the bound BATCh blocks names columns that a TPLOt of the
// same problem writes: a DeckError at the offending field otherwise. Run after
// binding, before computing.
void checkPlotColumns(const std::vector<std::vector<Macro>>& batches, const Parameters& params);

}  // namespace c2d
