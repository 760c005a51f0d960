#pragma once
// The solution commands (BATCh language): each is a small class with a
// declared spec, a bind step (static checks, claiming its data records after
// END, in deck order, before anything is computed) and a run step.
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "macro/deck/CommandSpec.h"
#include "macro/deck/Macro.h"
#include "macro/deck/Parameters.h"
#include "macro/deck/Warnings.h"

namespace c2d {

class ProblemRun;

// What binding a problem's BATCh blocks learns for the checks that need all of
// them (FPROportional tables that no PROP defines), and where warnings go.
struct BindFacts {
  std::set<int> loadTables;  // proportional load tables defined by PROP (0 counts as 1)
  bool restart = false;      // a REST command: the load tables come from its file
  Warnings* warnings = nullptr;
};

// What bind() sees: the data records after the BATCh END, read in order, and a
// parameter table that PARA commands update as the deck is walked.
class BindContext {
 public:
  BindContext(const std::vector<Record>& data, Parameters& params, BindFacts* facts = nullptr)
      : data_(data), params_(params), facts_(facts ? facts : &own_) {}
  bool atEnd() const { return pos_ >= data_.size(); }
  const Record& peek() const { return data_[pos_]; }
  // Next data record; a DeckError at `who` when there is none.
  const Record& take(const Record& who, const char* what);
  // Records up to the next blank one (which is consumed too).
  std::vector<Record> takeSet(const Record& who, const char* what);
  void skipBlank() {
    if (!atEnd() && peek().blank()) ++pos_;
  }
  Parameters& params() { return params_; }
  std::size_t position() const { return pos_; }
  std::set<int>& loadTables() { return facts_->loadTables; }
  void noteRestart() { facts_->restart = true; }
  void warn(const SourceLoc& loc, const std::string& message, const std::string& text) {
    if (facts_->warnings) facts_->warnings->add(loc, message, text);
  }

 private:
  const std::vector<Record>& data_;
  Parameters& params_;
  BindFacts own_;
  BindFacts* facts_;
  std::size_t pos_ = 0;
};

// How control continues after a command.
enum class Flow {
  Next,      // go on with the next command
  ExitLoop,  // leave the innermost loop (converged Newton iteration, TIME reached tmax)
  Stop,      // STOP: end the run
};

class SolutionCommand {
 public:
  virtual ~SolutionCommand() = default;
  virtual CommandSpec spec() const = 0;
  virtual void bind(Macro& m, BindContext& ctx) const;  // default: evaluate the numbers
  virtual Flow run(const Macro& m, ProblemRun& run) const = 0;
};

class SolutionCommands {
 public:
  SolutionCommands();  // the explicit registration list (macro/solution/SolutionCommands.cpp)
  const CommandRegistry& registry() const { return registry_; }
  const SolutionCommand* find(const std::string& word) const;

 private:
  void add(std::unique_ptr<SolutionCommand> c);
  CommandRegistry registry_;
  std::vector<std::unique_ptr<SolutionCommand>> commands_;
};

// Parses the records of a BATCh block into commands (LOOP/NEXT matched) and
// binds them in deck order, claiming their data records. Throws DeckError.
// LOOP ... NEXT may nest DeckLimits::kMaxLoopDepth deep. facts, when given,
// collects what the binding learns across the blocks of a problem.
std::vector<Macro> bindBatch(const std::vector<Record>& commands, const std::vector<Record>& data,
                             const SolutionCommands& table, Parameters& params,
                             BindFacts* facts = nullptr);

}  // namespace c2d
