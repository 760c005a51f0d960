#include "macro/Sweep.h"

#include <cctype>
#include <cstdint>
#include <cstdio>

namespace c2d {

std::string formatSweepValue(double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", value == 0 ? 0.0 : value);
  return buf;
}

std::string sweepTag(const SweepValues& values) {
  std::string tag;
  for (const auto& [name, v] : values) {
    if (!tag.empty()) tag += '_';
    tag += name + "=" + formatSweepValue(v);
  }
  // Names are parameter names and values come from %g: only "inf"/"nan" could
  // surprise a shell, and they stay plain letters.
  for (char& c : tag)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+' ||
          c == '=' || c == '_'))
      c = '_';
  return tag;
}

std::string fitFileStem(const std::string& stem, std::size_t max) {
  if (stem.size() <= max || max < 10) return stem;
  std::uint32_t h = 2166136261u;  // FNV-1a
  for (unsigned char c : stem) h = (h ^ c) * 16777619u;
  char hex[12];
  std::snprintf(hex, sizeof hex, "_%08x", static_cast<unsigned>(h));
  return stem.substr(0, max - 9) + hex;
}

std::string sweepLabel(const SweepValues& values) {
  std::string label;
  for (const auto& [name, v] : values) {
    if (!label.empty()) label += ", ";
    label += name + " = " + formatSweepValue(v);
  }
  return label;
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
      "(values are expressions without blanks; several names are zipped and need the same "
      "number of values), ended by a blank record. The next problem (with the PARAmeter blocks "
      "between the sweep and it, evaluated after the sweep values are set) runs once per value "
      "set; each run's outputs are tagged with its values, <stem>_ks=-393_tplot.csv, and every "
      "PLOT,CURVe of the runs is overlaid at the end of the deck in <stem>_<y>_vs_<x>.svg with "
      "one legend entry per run ('ks = -393'). FEAP's LOOP,,n ... NEXT around a problem with a "
      "PARAmeter block inside still works; its runs are <stem>_1, <stem>_2, ... "
      "A sweep is a study of plans (blast times, element numbers: any numeric field takes "
      "parameters): a run that fails is reported and the others run (exit status 2 if any "
      "failed), and the study ends with <stem>_plans.csv, one row per run: run number, stem, "
      "swept values, status (ok/failed) and reason, the debris figures. collapse2d run "
      "--shard i/n runs the i-th of n interleaved parts; collapse2d merge joins the parts.";
  s.section = CommandSection::Mesh;
  s.data = DataForm::Records;
  s.dataSyntax = "name = v1 v2 ...";
  s.dataFields = {{"name", FieldKind::Text, {}, "parameter name"},
                  {"v1 v2 ...", FieldKind::Expression, {}, "its value in each run"}};
  registry.add(std::move(s));
}

}  // namespace c2d
