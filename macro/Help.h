#pragma once
// --help, generated from the same declared specs the parser uses.
#include <ostream>
#include <string>

#include "macro/deck/SolutionCommand.h"

namespace c2d {

void printAllHelp(std::ostream& os, const SolutionCommands& solution);
// One command (any section); false when no command matches.
bool printCommandHelp(std::ostream& os, const SolutionCommands& solution, const std::string& word);

}  // namespace c2d
