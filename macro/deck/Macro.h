#pragma once
// A solution command bound from a BATCh record: its command, option word,
// numeric fields (expressions, evaluated when it runs), the data records it
// claimed after the BATCh END, and for LOOP its body.
#include <string>
#include <vector>

#include "macro/deck/Expression.h"
#include "macro/deck/Record.h"

namespace c2d {

class SolutionCommand;

struct Macro {
  const SolutionCommand* command = nullptr;
  std::string key;                  // four-character key, lower case ("tang")
  Record record;
  std::string option;               // the second field, lower case ("line" in TANG,LINE,1)
  std::string optionText;           // the same as written (file names keep their case)
  std::vector<Expression> numbers;  // the fields after the option
  std::vector<Record> data;         // data records read after END
  std::vector<Macro> body;          // LOOP ... NEXT
  Record next;                      // the NEXT record of a LOOP

  bool is(const char* k) const { return key == k; }
  // Whether number i was written (a field present, even empty).
  bool has(std::size_t i) const { return i < numbers.size(); }
  // The body holds a Newton iteration (TANG/UTAN/SOLV) directly: a Newton loop.
  bool newtonLoop() const;
};

}  // namespace c2d
