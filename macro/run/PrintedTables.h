#pragma once
// The tables the solution commands print in the log (macro/run/Report.h lays
// them out): nodal values (DISP, VELO, ACCE, REAC) in the digits FORM chose,
// section forces and the hinge table (STRE).
#include <ostream>
#include <vector>

#include "core/Error.h"
#include "core/Model.h"
#include "macro/deck/Macro.h"
#include "macro/deck/Parameters.h"
#include "solvers/Analysis.h"

namespace c2d {

class PrintedTables {
 public:
  explicit PrintedTables(std::ostream& log) : log_(log) {}

  // FORM,LONG / FORM,SHORt: the digits of the nodal tables (FEAP's fmt_long).
  void setLongFormat(bool on) { longFormat_ = on; }
  // DISP, VELO, ACCE or REAC (m's name) of the nodes of m's range in use; the
  // reactions' failure, when they cannot be evaluated, prints nothing.
  Status nodal(const Macro& m, const Parameters& params, const Model& model,
               Analysis& analysis) const;
  // STRE: the section forces of the elements of m's range, every element
  // evaluated at the current state first (its failure prints nothing).
  Status stresses(const Macro& m, const Parameters& params, Model& model,
                  Analysis& analysis) const;
  // STRE,HINGe: the softening hinges; hingeSteps: the step each one formed.
  void hinges(Model& model, const Analysis& analysis, const std::vector<int>& hingeSteps) const;

 private:
  std::ostream& log_;
  bool longFormat_ = false;
};

}  // namespace c2d
