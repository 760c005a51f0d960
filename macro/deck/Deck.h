#pragma once
// The parsed deck (section 3 of the deck language):
//   [PARAmeter blocks, top-level LOOP ... NEXT]
//   FEAP title / control record / mesh commands / END
//   BATCh ... END / data records / [more BATCh ... END] / [FEAP ...] / STOP
// Structure only: expressions are parsed (syntax checked) but evaluated when
// the deck runs, so that a top-level LOOP with a PARAmeter block inside can
// change them from one pass to the next.
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "macro/deck/Expression.h"
#include "macro/deck/Parameters.h"
#include "macro/deck/Record.h"

namespace c2d {

// name = expression
struct ParamAssign {
  std::string name;  // lower case
  Expression value;
  Record record;
};

// PARAmeter (or CONStant) and its records up to the blank record.
struct ParamBlock {
  Record head;
  std::vector<ParamAssign> assigns;

  // Evaluates the assignments in order (a later one may use an earlier one); a
  // name a study sets for each run (Parameters::protect) is a DeckError there.
  void apply(Parameters& params) const {
    for (const auto& a : assigns) params.assign(a.name, a.value.eval(params), a.record[0]);
  }
};

// A mesh command record and its data records (without the blank that ends them).
struct MeshCommand {
  Record head;
  std::vector<Record> data;
};

using MeshItem = std::variant<MeshCommand, ParamBlock>;

struct BatchBlock {
  Record head;                   // BATCh
  std::vector<Record> commands;  // between BATCh and END, blank records dropped
  Record end;                    // the END record
  // Records after END up to the next BATCh, FEAP, STOP, LOOP or NEXT (or a
  // top-level PARAmeter block before them), blank records kept: they end data sets.
  std::vector<Record> data;
};

struct Problem {
  Record head;        // FEAP record
  std::string title;  // the FEAP record after its first word
  Record control;     // numnp numel nummat ndm ndf nen (blank when given by keywords)
  // FEAP's keyword form of the control record instead: records of 'keyword value'
  // pairs (NODEs n, ELEMents n, MATErial n, DIMEnsion, DOFS, ELNOdes, or NUMNp,
  // NUMEl, NUMMat, NDM, NDF, NEN), ended by a blank record.
  std::vector<Record> controlKeywords;
  std::vector<MeshItem> mesh;
  Record meshEnd;  // END of the mesh input
  std::vector<BatchBlock> batches;
};

struct TopLoop;
struct TopSweep;
struct TopEnsemble;
using TopItem = std::variant<ParamBlock, Problem, TopLoop, TopSweep, TopEnsemble>;

// LOOP,,n ... NEXT around whole problems: FEAP's parameter study.
struct TopLoop {
  Record head;
  Expression count;
  std::vector<TopItem> body;
  Record next;
};


// One value of a sweep (an expression), or a range lo:step:hi: lo, lo + step,
// ... up to hi (macro/draws/Sweep.h sweepValues).
struct SweepItem {
  Expression value;  // the value, or a range's lo
  std::optional<Expression> step, last;
  bool range() const { return step.has_value(); }
};

// One record of a SWEEp block, name = v1 v2 ..., with the records that continue
// its list of values (records without 'name =').
struct SweepVariable {
  std::string name;  // as written (tags and legends keep its case)
  std::vector<SweepItem> items;
  Record record;
  // The number of values when no item is a range (known before evaluating).
  std::optional<std::size_t> fixedCount() const {
    for (const SweepItem& i : items)
      if (i.range()) return std::nullopt;
    return items.size();
  }
};

// [ext] SWEEp: records 'name = v1 v2 ...' (several names zipped: the same number
// of values each), ended by a blank record. The next problem runs once per value
// set, with the PARAmeter blocks between the sweep and the problem evaluated
// after the sweep values are set, so that they may derive from them.
struct TopSweep {
  Record head;
  std::vector<SweepVariable> variables;
  std::vector<TopItem> body;  // PARAmeter blocks (an ENSEmble), then the problem
};

// [ext] One drawn parameter of an ENSEmble: name = NORMal mean sd | LOGNormal
// median cov | UNIForm lo hi (macro/draws/Distribution.h).
struct DrawRecord {
  std::string name;  // as written
  std::string law;   // "norm", "logn" or "unif"
  Expression a, b;
  Record record;
};

// [ext] ENSEmble,,n,seed: every plan (every value set of a SWEEp, or the lone
// problem) runs n times, sample k with the draws of (seed, k)
// (macro/draws/Ensemble.h). Records: drawn parameters, JITTer,,dx,fdt and
// DETOnators (,,sd,cov | ,PYROtechnic | ,ELECtronic), ended by a blank record.
struct TopEnsemble {
  Record head;
  Expression samples, seed;
  std::vector<DrawRecord> draws;
  std::optional<Record> jitter, detonators;
  std::vector<TopItem> body;  // PARAmeter blocks, then the problem
};

struct Deck {
  std::string path;
  std::vector<TopItem> items;
  std::optional<Record> stop;  // absent when the file ends without STOP
};

}  // namespace c2d
