#pragma once
// The unit of every field of the deck commands in the decks' system of units,
// kN, m, s, t (stresses kN/m^2, densities t/m^3, moments kN m, rotations rad,
// gravity 9.81 m/s^2), shown by --help next to each field, and the --help
// UNITs text on consistent systems. The program itself has no units: every
// number of a deck is in one consistent system, and its results are in it.
#include <optional>
#include <string>
#include <string_view>

#include "macro/deck/CommandSpec.h"

namespace c2d::units {

// The unit of field `field` of a command of `section` whose four-letter key is
// `key` ("" for text, "-" for numbers without dimension); none when the table
// has no entry.
std::optional<std::string> ofField(CommandSection section, std::string_view key,
                                   std::string_view field);
// The units of the command's data records as one line ("x, y [m]; node, ng
// [-]"); empty for a command without data records in the table.
std::string ofDataRecords(CommandSection section, std::string_view key);
// The text of --help UNITs.
std::string systemHelp();

}  // namespace c2d::units
