#pragma once
// The columns of a time history: those a TPLOt command writes (as TimeHistory
// names them) and those a PLOT,CURVe field reads, with the check that every
// PLOT,CURVe reads columns a TPLOt of its problem writes.
#include <cstddef>
#include <string>
#include <vector>

#include "macro/deck/Macro.h"
#include "macro/deck/Parameters.h"

namespace c2d {

// The columns of a TPLOt command as its records name them (time and prop
// first), with the parameters given; the names TimeHistory writes.
std::vector<std::string> timeHistoryColumns(const Macro& tplot, const Parameters& params);

// The TPLOt column that field i of a PLOT,CURVe record names ("disp_11_1";
// the number may be an expression, "disp_n+1_1"), or "" when it names none.
std::string resolveColumn(const Record& rec, std::size_t i, const Parameters& params);
// The hint that lists the kinds of TPLOt columns.
std::string columnHint();

// Every PLOT,CURVe of the bound BATCh blocks names columns that a TPLOt of the
// same problem writes: a DeckError at the offending field otherwise. Run after
// binding, before computing.
void checkPlotColumns(const std::vector<std::vector<Macro>>& batches, const Parameters& params);

}  // namespace c2d
