#pragma once
// What the solution command families (ControlCommands, NewtonCommands,
// TimeCommands, OutputCommands, ModelCommands, RestartCommands) share: the
// fields of their specs, their located errors, and each family's list of
// commands, which SolutionCommands registers in that order.
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "macro/deck/SolutionCommand.h"

namespace c2d {

std::vector<std::unique_ptr<SolutionCommand>> controlCommands();  // LOOP NEXT PARA MESH STOP
std::vector<std::unique_ptr<SolutionCommand>> newtonCommands();   // TANG UTAN FORM SOLV TOL
std::vector<std::unique_ptr<SolutionCommand>> timeCommands();     // DT TIME BACK PROP ARCL AUTO DYNA
std::vector<std::unique_ptr<SolutionCommand>> outputCommands();   // DISP ... STRE TPLOt PLOT PVIEw
std::vector<std::unique_ptr<SolutionCommand>> modelCommands();    // HINGe2joint REMOve
std::vector<std::unique_ptr<SolutionCommand>> restartCommands();  // SAVE REST

namespace batchspec {

inline FieldSpec num(std::string name, std::string doc, std::string def = {}) {
  return {std::move(name), FieldKind::Expression, std::move(def), std::move(doc)};
}
inline FieldSpec word(std::string name, std::string doc, std::string def = {}) {
  return {std::move(name), FieldKind::Text, std::move(def), std::move(doc)};
}
inline CommandSpec solution(std::string name, std::string doc, std::vector<FieldSpec> fields,
                            std::string dataSyntax = {}) {
  CommandSpec s;
  s.name = std::move(name);
  s.doc = std::move(doc);
  s.fields = std::move(fields);
  s.section = CommandSection::Solution;
  if (!dataSyntax.empty()) {
    s.data = DataForm::Records;
    s.dataSyntax = std::move(dataSyntax);
  }
  return s;
}

[[noreturn]] inline void fail(const Macro& m, std::size_t field, const std::string& what) {
  throw DeckError(m.record.fieldLoc(field), what, m.record.excerpt(m.record.fieldLoc(field)));
}

inline std::string formatNumber(double v) {
  std::ostringstream s;
  s.precision(12);
  s << v;
  return s.str();
}

// Number i (record field 2 + i) when it is written, not empty.
inline bool written(const Macro& m, std::size_t i) {
  return m.has(i) && !m.record.text(2 + i).empty();
}

// A time step or minimum step written in number i must be positive; checked when
// the command is bound (before computing) and again when it runs (a parameter
// may have changed in between).
inline void checkPositive(const Macro& m, std::size_t i, const Parameters& p,
                          const std::string& what) {
  if (!written(m, i)) return;
  const double v = m.numbers[i].eval(p);
  if (!(v > 0)) fail(m, 2 + i, what + " must be positive, got " + formatNumber(v));
}

}  // namespace batchspec
}  // namespace c2d
