#pragma once
// The bracketing line search of TANG,LINE (and of a plain TANG step whose
// iterations cycle): a step length s along the Newton correction du with
// |g(s)| <= 0.8 |g(0)|, g(s) = du . R(u + s du).
//
// For a convex incremental potential (hardening) g falls monotonically through
// zero: once g(s) changes sign the root is bracketed and regula falsi
// (Illinois) keeps it so; before that the secant extrapolates (up to s = 4).
// With a kinked law (Kh2/EI = 1/285 in the paper's data) the full Newton step
// from an overshooting iterate can land past the reverse yield surface, and
// plain Newton then cycles; the bracketed search does not.
//
// A template (not std::function) so that the Newton loop allocates nothing.
#include <cmath>

#include "core/Error.h"

namespace c2d {

// g0 = g(0); evalG(s, out) evaluates g(s) and leaves the state as it found it.
template <class EvalG>
double bracketedLineSearch(double g0, EvalG&& evalG) {
  double g1 = 0;
  if (!evalG(1.0, g1) || !(std::abs(g1) > 0.8 * std::abs(g0))) return 1.0;
  double sLo = 0, gLo = g0, sHi = 1, gHi = g1, sn = 1, gn = g1;
  int side = 0;
  for (int k = 0; k < 10 && std::abs(gn) > 0.8 * std::abs(g0); ++k) {
    const bool bracketed = (gLo > 0) != (gHi > 0);
    if (bracketed) {
      sn = sHi - gHi * (sHi - sLo) / (gHi - gLo);
    } else if (gHi != gLo && std::abs(gHi) < std::abs(gLo)) {
      sn = std::fmin(4.0, sHi - gHi * (sHi - sLo) / (gHi - gLo));
    } else {
      break;  // g grows along the direction: no better step to find here
    }
    if (!evalG(sn, gn)) break;
    if (!bracketed) {
      sLo = sHi;
      gLo = gHi;
      sHi = sn;
      gHi = gn;
    } else if ((gn > 0) == (gLo > 0)) {
      sLo = sn;
      gLo = gn;
      if (side == 1) gHi *= 0.5;
      side = 1;
    } else {
      sHi = sn;
      gHi = gn;
      if (side == -1) gLo *= 0.5;
      side = -1;
    }
  }
  return sn;
}

}  // namespace c2d
