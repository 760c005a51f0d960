// The solution commands of the BATCh language (deck language section 6): the
// explicit registration list of every family's commands (ControlCommands,
// NewtonCommands, TimeCommands, OutputCommands, ModelCommands,
// RestartCommands: one small class per command, with its declared spec, its
// bind step and its run step). The registry's lookup and the binding of a
// BATCh block are macro/deck/SolutionCommand.cpp's.
#include <memory>
#include <utility>

#include "macro/solution/SolutionCommandKit.h"

namespace c2d {

SolutionCommands::SolutionCommands() : registry_("Solution commands (BATCh ... END)") {
  for (auto family : {controlCommands, newtonCommands, timeCommands, outputCommands,
                      modelCommands, restartCommands})
    for (std::unique_ptr<SolutionCommand>& c : family()) add(std::move(c));
}

}  // namespace c2d
