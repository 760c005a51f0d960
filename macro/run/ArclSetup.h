#pragma once
// ARCL in a BATCh block: the path following its option and records choose,
// set on the analysis. ARCL,off: none. ARCL[,,kfl] without data, kfl < 4:
// FEAPpv's arc length, whose first load increment is the first step's dt
// (known when that step starts). A data record 'dlambda0' (or 'ndamp
// dlambda0'): an arc length with that first increment. kfl >= 4 and 'node dof
// du': displacement control of that free dof.
#include <ostream>

#include "core/Model.h"
#include "macro/deck/Macro.h"
#include "macro/deck/Parameters.h"
#include "solvers/Analysis.h"

namespace c2d {

// Sets the analysis's path following as the command says and logs it; true:
// FEAPpv's arc length, to be set up when the first step starts. DeckError at
// a node or dof that displacement control cannot take.
bool setUpArcl(const Macro& m, Analysis& analysis, const Model& model,
                      const Parameters& params, std::ostream& log);

}  // namespace c2d
