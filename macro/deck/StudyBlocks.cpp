#include "macro/deck/StudyBlocks.h"

#include <algorithm>
#include <string>
#include <utility>

#include "macro/deck/Parameters.h"
#include "macro/deck/Record.h"

namespace c2d {

namespace {

[[noreturn]] void failAt(const Record& r, std::size_t i, const std::string& msg,
                         const std::string& hint = {}) {
  throw DeckError(r.fieldLoc(i), msg, r.excerpt(r.fieldLoc(i)), hint);
}

bool written(const Record& r, std::size_t i) { return i < r.size() && !r[i].text.empty(); }

const char* const kDrawSyntax = "name = NORMal mean sd | LOGNormal median cov | UNIForm lo hi";


// Variables whose numbers of values are known (no ranges) are zipped: the last
// one has as many as the first such.
void checkSweepCounts(const std::vector<SweepVariable>& vars) {
  const SweepVariable& v = vars.back();
  const auto n = v.fixedCount();
  if (!n) return;
  for (const SweepVariable& w : vars) {
    const auto m = w.fixedCount();
    if (&w == &v || !m || *m == *n) continue;
    throw DeckError(v.record[0].loc,
                    "'" + v.name + "' has " + std::to_string(*n) + " values and '" + w.name +
                        "' (line " + std::to_string(w.record.loc.line) + ") " + std::to_string(*m) +
                        ": the variables of a sweep are zipped, one value of each per run",
                    v.record.excerpt(v.record[0].loc));
  }
}

}  // namespace

std::vector<SweepItem> parseSweepItems(const Record& rec, std::size_t first) {
  std::vector<SweepItem> items;
  for (std::size_t i = first; i < rec.size(); ++i) {
    const Field& f = rec[i];
    if (f.text.empty())
      throw DeckError(f.loc, "empty value in a sweep", rec.excerpt(f.loc),
                      "separate the values by blanks (two commas make an empty field)");
    if (f.text.find(':') == std::string::npos) {
      items.push_back({Expression::parse(f), {}, {}});
      continue;
    }
    // lo:step:hi, each part an expression.
    std::vector<std::pair<std::string, int>> parts;  // text, column
    std::size_t start = 0;
    for (std::size_t c = 0; c <= f.text.size(); ++c)
      if (c == f.text.size() || f.text[c] == ':') {
        parts.emplace_back(f.text.substr(start, c - start), f.loc.col + static_cast<int>(start));
        start = c + 1;
      }
    if (parts.size() != 3)
      throw DeckError(f.loc, "a range of sweep values is lo:step:hi, got '" + f.text + "'",
                      rec.excerpt(f.loc), "e.g. 0:0.01:1 gives 0, 0.01, ..., 1");
    std::vector<Expression> e;
    for (const auto& [text, col] : parts) {
      SourceLoc at = f.loc;
      at.col = col;
      if (text.empty())
        throw DeckError(at, "a part of the range '" + f.text + "' is empty", rec.excerpt(at),
                        "a range is lo:step:hi");
      e.push_back(Expression::parse(text, at, rec.line));
    }
    items.push_back({e[0], e[1], e[2]});
  }
  return items;
}

void addSweepRecord(TopSweep& sw, const Record& rec, bool assignment) {
  // A record without 'name =' continues the values of the variable before it
  // (a record holds at most 256 characters).
  if (!assignment) {
    if (sw.variables.empty())
      throw DeckError(rec[0].loc, "expected 'name = v1 v2 ...'", rec.excerpt(rec[0].loc),
                      "a record without 'name =' continues the values of the record before "
                      "it");
    SweepVariable& v = sw.variables.back();
    for (SweepItem& item : parseSweepItems(rec, 0)) v.items.push_back(std::move(item));
    return;
  }
  if (!sw.variables.empty()) checkSweepCounts(sw.variables);
  if (!Parameters::validName(rec[0].text))
    throw DeckError(rec[0].loc, "expected 'name = v1 v2 ...', and '" + rec[0].text +
                                    "' is not a parameter name",
                    rec.excerpt(rec[0].loc));
  SweepVariable v;
  v.name = rec[0].text;
  v.record = rec;
  v.items = parseSweepItems(rec, 1);
  if (v.items.empty())
    throw DeckError(rec.fieldLoc(1), "sweep variable '" + v.name + "' has no values",
                    rec.excerpt(rec.fieldLoc(1)), "write " + v.name + " = v1 v2 ...");
  for (const SweepVariable& w : sw.variables)
    if (toLower(w.name) == toLower(v.name))
      throw DeckError(rec[0].loc,
                      "'" + v.name + "' is swept twice (line " + std::to_string(w.record.loc.line) +
                          ")",
                      rec.excerpt(rec[0].loc));
  sw.variables.push_back(std::move(v));
}

void checkSweepVariables(const TopSweep& sw) {
  const Field& at = sw.head[0];
  if (sw.variables.empty())
    throw DeckError(at.loc, "SWEEp block without variables", sw.head.excerpt(at.loc),
                    "write records 'name = v1 v2 ...' ended by a blank record");
  checkSweepCounts(sw.variables);
}

void readEnsembleHead(TopEnsemble& e) {
  const Record& h = e.head;
  if (h.size() > 4)
    throw DeckError(h[4].loc, "too many fields: ENSEmble,,n,seed", h.excerpt(h[4].loc));
  if (h.size() < 3 || h[2].text.empty())
    throw DeckError(h.fieldLoc(2), "ENSEmble needs the number of samples: ENSEmble,,n,seed",
                    h.excerpt(h.fieldLoc(2)), "e.g. ENSEmble,,20,1");
  if (!h[1].text.empty())
    throw DeckError(h[1].loc, "ENSEmble takes numbers only: ENSEmble,,n,seed", h.excerpt(h[1].loc));
  e.samples = Expression::parse(h[2]);
  if (h.size() > 3 && !h[3].text.empty()) e.seed = Expression::parse(h[3]);
}

void addEnsembleRecord(TopEnsemble& e, const Record& r, bool assignment) {
  if (!assignment && (r.is("JITTer") || r.is("DETOnators"))) {
    const bool jitter = r.is("JITTer");
    if (jitter ? e.jitter.has_value() : e.detonators.has_value())
      failAt(r, 0, std::string(jitter ? "JITTer" : "DETOnators") + " is given twice in this block");
    if (r.size() > 4)
      failAt(
          r, 4,
          "too many fields: " + std::string(jitter ? "JITTer,,dx,fdt" : "DETOnators,kind,sd,cov"));
    if (jitter && written(r, 1))
      failAt(r, 1, "JITTer takes numbers only: JITTer,,dx,fdt", "e.g. JITTer,,1e-6,0.01");
    if (!jitter && written(r, 1) && !keywordMatches(r[1].text, "PYROtechnic") &&
        !keywordMatches(r[1].text, "ELECtronic"))
      failAt(r, 1, "unknown kind of detonator '" + r[1].text + "'",
             "DETOnators,PYROtechnic, DETOnators,ELECtronic or DETOnators,,sd,cov");
    for (std::size_t i = 2; i < r.size(); ++i)
      if (written(r, i)) Expression::parse(r[i]);
    (jitter ? e.jitter : e.detonators) = r;
    return;
  }
  if (!assignment || !Parameters::validName(r[0].text))
    failAt(r, 0,
           "expected a drawn parameter '" + std::string(kDrawSyntax) + "', JITTer or DETOnators");
  const std::string name = r[0].text;
  if (r.size() < 2 || !written(r, 1)) failAt(r, 1, "'" + name + "' needs a law: " + kDrawSyntax);
  DrawRecord d;
  d.name = name;
  d.record = r;
  if (keywordMatches(r[1].text, "NORMal"))
    d.law = "norm";
  else if (keywordMatches(r[1].text, "LOGNormal"))
    d.law = "logn";
  else if (keywordMatches(r[1].text, "UNIForm"))
    d.law = "unif";
  else
    failAt(r, 1, "unknown law '" + r[1].text + "'", kDrawSyntax);
  if (r.size() != 4 || !written(r, 2) || !written(r, 3))
    failAt(r, r.size() > 4 ? 4 : std::min<std::size_t>(r.size(), 3),
           "'" + name + "' needs two numbers: " + kDrawSyntax);
  d.a = Expression::parse(r[2]);
  d.b = Expression::parse(r[3]);
  for (const DrawRecord& o : e.draws)
    if (toLower(o.name) == toLower(name))
      failAt(r, 0,
             "'" + name + "' is drawn twice (line " + std::to_string(o.record.loc.line) + ")");
  e.draws.push_back(std::move(d));
}

// A name both swept and drawn would give its runs two values.
void checkDrawsNotSwept(const TopEnsemble& e, const TopSweep& sw) {
  for (const DrawRecord& d : e.draws)
    for (const SweepVariable& v : sw.variables)
      if (toLower(d.name) == toLower(v.name))
        throw DeckError(d.record[0].loc,
                        "'" + d.name + "' is both drawn and swept (line " +
                            std::to_string(v.record.loc.line) + ")",
                        d.record.excerpt(d.record[0].loc), "draw or sweep it, not both");
}

void registerDeckBlocks(CommandRegistry& registry) {
  CommandSpec feap;
  feap.name = "FEAP";
  feap.doc =
      "Start of a problem: 'FEAP * * title', then the control record 'numnp numel nummat ndm "
      "ndf nen' (zeros: counted; frames have ndm 2, ndf 3, nen 2), or FEAP's keyword form: "
      "records of 'keyword value' pairs in any order, NODEs, ELEMents, MATErial, DIMEnsion, "
      "DOFS, ELNOdes (or NUMNp, NUMEl, NUMMat, NDM, NDF, NEN), e.g. 'NODES=10 ELEMENTS=9 "
      "MATERIAL=1', ended by a blank record (absent: counted, 2, 3, 2). Then the mesh "
      "commands up to END, and BATCh blocks.";
  feap.section = CommandSection::Mesh;
  feap.data = DataForm::Records;
  feap.dataSyntax = "numnp numel nummat ndm ndf nen | keyword value ...";
  registry.add(std::move(feap));

  CommandSpec s;
  s.name = "SWEEp";
  s.doc =
      "[ext] Parameter sweep, a top-level block before a problem: records 'name = v1 v2 ...' "
      "(values are expressions without blanks, or ranges lo:step:hi giving lo, lo + step, ... up "
      "to hi; a record without 'name =' continues the values of the one before; several names "
      "are zipped and need the same number of values), ended by a blank record. The next problem "
      "(with the PARAmeter blocks between the sweep and it, evaluated after the sweep values are "
      "set; they may use a swept name, not set it) runs once per value set (n times with an "
      "ENSEmble before or after the sweep); each run's outputs are tagged with its values, "
      "<stem>_ks=-393_tplot.csv, and every "
      "PLOT,CURVe of the runs is overlaid at the end of the deck in <stem>_<y>_vs_<x>.svg with "
      "one legend entry per run ('ks = -393'). FEAP's LOOP,,n ... NEXT around a problem with a "
      "PARAmeter block inside still works; its runs are <stem>_1, <stem>_2, ... "
      "A sweep is a study of plans (blast times, element numbers: any numeric field takes "
      "parameters): a run that fails is reported and the others run (exit status 2 if any "
      "failed), and the study ends with <stem>_plans.csv, one row per run: run number, stem, "
      "swept values, status (ok/failed) and reason, the debris figures. collapse2d run "
      "--shard i/n runs the i-th of n interleaved parts; collapse2d merge checks and joins the "
      "parts (tables and overlays); collapse2d run -j N runs the runs in N processes. "
      "A record 'PLAN = name1 name2 ...' names the plans (zipped like a variable; a name is a "
      "letter, then letters, digits or '_'; it sets no parameter): plan k's outputs are "
      "<stem>_<name k>_..., and its legend entries, picture titles and the tables (a column "
      "`name` after `stem` in <stem>_plans.csv and <stem>_ensemble.csv, after `plan` in an "
      "ensemble's plans and sensitivity tables) say its name instead of its values. With "
      "BLASt's ON field, plans that blast different column lines are one sweep: "
      "'PLAN = left right', 'on1 = 1 0', 'on2 = 0 1'.";
  s.section = CommandSection::Mesh;
  s.data = DataForm::Records;
  s.dataSyntax = "name = v1 v2 ... (a value, or a range lo:step:hi); v3 v4 ... (continued)";
  s.dataFields = {{"name", FieldKind::Text, {}, "parameter name"},
                  {"v1 v2 ...", FieldKind::Expression, {}, "its value in each run"}};
  registry.add(std::move(s));
}

void registerEnsembleBlock(CommandRegistry& registry) {
  CommandSpec s;
  s.name = "ENSEmble";
  s.doc =
      "[ext] Ensemble, a top-level block before a problem (before or after its SWEEp): every plan "
      "runs n times, sample k (1..n) with the draws of (seed, k) alone, the same in every plan "
      "(common random numbers), shard and rerun. Records up to a blank record: 'name = NORMal "
      "mean sd', 'name = LOGNormal median cov' (median and coefficient of variation), 'name = "
      "UNIForm lo hi': a parameter drawn per sample, set after the sweep's values and before "
      "the PARAmeter blocks that follow (which may use it, not set it); 'JITTer,,dx,fdt': every "
      "node moved by a random offset of at most dx (default 1e-6, coincident nodes together) and "
      "every time step of a dynamic analysis scaled by a factor in 1 +- fdt (default 0.01); "
      "'DETOnators,,sd,cov': "
      "every BLASt time t scattered by a normal number of standard deviation sqrt(sd^2 + (cov "
      "t)^2) (DETOnators,ELECtronic: sd = 1 ms; DETOnators,PYROtechnic: cov = 3 %). Outputs: "
      "<stem>_ensemble.csv (a row per run: its draws, status, steps, Newton iterations, step "
      "cuts, energy balance error, debris figures), <stem>_timing.csv (each run's CPU "
      "seconds), <stem>_plans.csv (a row per plan: quantiles of the "
      "debris figures, p_outside with its 95 % Wilson interval, p_moving), "
      "<stem>_sensitivity.csv (rank correlations of the drawn values with the debris figures), "
      "<stem>_ensemble.svg; the log names the best plan and whether its lead is significant. "
      "Sample 1 of each plan writes every output of its run; the others their time history and "
      "debris rows and a short log.";
  s.fields = {{"-", FieldKind::Text, {}, ""},
              {"n", FieldKind::Expression, {}, "samples per plan"},
              {"seed", FieldKind::Expression, "1", "seed of the draws (0 or more)"}};
  s.section = CommandSection::Mesh;
  s.data = DataForm::Records;
  s.dataSyntax =
      "name = NORMal mean sd | LOGNormal median cov | UNIForm lo hi; JITTer,,dx,fdt; "
      "DETOnators,,sd,cov | DETOnators,PYROtechnic | DETOnators,ELECtronic";
  registry.add(std::move(s));

  CommandSpec d;
  d.name = "DETOnators";
  d.doc =
      "[ext] A record of the ENSEmble block: every BLASt time t scattered in each sample by a "
      "normal number of standard deviation sqrt(sd^2 + (cov t)^2), independently per record "
      "and sample (DETOnators,ELECtronic: sd = 1 ms, the accuracy of electronic delay "
      "detonators; DETOnators,PYROtechnic: cov = 3 % of the nominal delay). Bounds: a draw "
      "never goes before t = 0 (a detonator does not fire before the firing; a draw below 0 "
      "is taken as 0). A blast drawn into a static step (before DYNAmic) fails its sample at "
      "that step, naming the BLASt record, its nominal and drawn times: the sample would "
      "otherwise go on without the blasted members held statically, which is no plan of the "
      "deck. The drawn times are the blast_1, blast_2, ... columns of <stem>_ensemble.csv.";
  d.fields = {{"kind", FieldKind::Text, {}, "ELECtronic, PYROtechnic or empty"},
              {"sd", FieldKind::Expression, "0", "standard deviation of a blast time (s)"},
              {"cov", FieldKind::Expression, "0", "the same, per unit of the nominal time"}};
  d.section = CommandSection::Mesh;
  registry.add(std::move(d));
}

}  // namespace c2d
