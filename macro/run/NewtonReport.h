#pragma once
// What the log and the error say of a Newton loop that failed: the step's
// iterations with the largest residual, and what to try.
#include <string>

namespace c2d {

class Analysis;
class EnergyWatch;

// The step's iterations (residual, energy |du.R|) and the node and dof of the
// largest residual, as indented lines.
std::string newtonHistoryText(const Analysis& analysis);

// What to try after a failed Newton loop: `why` (the reason), whether it used
// the line search, its iteration count when it ran out of iterations (else 0);
// the energy the motion gained without work first, when it did (EnergyWatch).
std::string newtonAdvice(Analysis& analysis, const EnergyWatch& energy, bool cutting,
                         const std::string& why, bool lineSearch, int iterations);

}  // namespace c2d
