#pragma once
// Sizes a deck may ask for. Arrays are sized from deck numbers (node, element
// and table numbers, counts of generated items), so every such number is
// checked against a limit before anything is allocated: a number the machine
// cannot hold is a located deck error, not a std::bad_alloc after a long wait
// nor an integer overflow in the generation arithmetic.
#include <cstddef>
#include <string>

#include "macro/deck/Record.h"

namespace c2d {

struct DeckLimits {
  // Largest node or element number: 10 million, less on a machine whose memory
  // cannot hold that many (about 4 kB per node or element through the analysis).
  static int maxNodes();
  static int maxElements() { return maxNodes(); }
  static constexpr int kMaxMaterials = 100000;  // material set numbers
  static constexpr int kMaxLoadTables = 10000;  // proportional load table numbers
  static constexpr int kMaxLoopDepth = 100;     // LOOP ... NEXT nested in one another
  static constexpr int kMaxRuns = 10000;        // passes of a top-level LOOP (each a run)
  // Largest |x| or |y| of a node, in the deck's length unit: contact, plots and
  // the energy square coordinates (1e155 squared is beyond a double).
  static constexpr double kMaxCoordinate = 1e9;
};

// DeckError at field i of r unless 1 <= value <= limit: "<what> <value> is beyond
// the largest <what> this program takes (<limit>)" or "must be positive".
void checkNumber(const Record& r, std::size_t i, long long value, long long limit,
                 const std::string& what, const std::string& why = {});

}  // namespace c2d
