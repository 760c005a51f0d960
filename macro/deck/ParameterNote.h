#pragma once
// A deck error at a field written with parameters ("GROUnd,,0,k" with k set in
// a PARAmeter block or a SWEEp) says what they were and where they were set:
//   deck.inp:30:13: error: penalty stiffness k must be positive (k = -1, set on line 3)
// ("set at file:line:col" when the parameter was set in another file)
// so that a reader need not look for the value that the message is about.
#include "core/Error.h"
#include "macro/deck/Parameters.h"

namespace c2d {

// The error with the values of the parameters its field names (those the
// table defines) appended to its message; the error itself when there are none.
DeckError noteParameters(const DeckError& e, const Parameters& params);

}  // namespace c2d
