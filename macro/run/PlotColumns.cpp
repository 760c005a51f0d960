// TPLOt's columns as TimeHistory writes them, and PLOT,CURVe's checks of
// the columns it reads.
#include "macro/run/PlotColumns.h"

#include <algorithm>

#include "macro/run/TimeHistory.h"

namespace c2d {

namespace {

[[noreturn]] void failData(const Record& rec, std::size_t field, const std::string& what,
                           const std::string& hint = {}) {
  throw DeckError(rec.fieldLoc(field), what, rec.excerpt(rec.fieldLoc(field)), hint);
}

void collect(const std::vector<Macro>& list, std::vector<const Macro*>& tplots,
             std::vector<const Macro*>& curves) {
  for (const Macro& m : list) {
    if (m.is("tplo")) tplots.push_back(&m);
    if (m.is("plot") && m.option.substr(0, 4) == "curv") curves.push_back(&m);
    collect(m.body, tplots, curves);
  }
}

}  // namespace

std::string columnHint() {
  std::string hint = "TPLOt columns: time, prop, disp_n_d, velo_n_d, acce_n_d, reac_n_d, stre_e_c";
  for (const char* w : kEnergyColumns) hint += std::string(", ") + w;
  return hint + ", arcl";
}

// The TPLOt column a PLOT,CURVe field names, as TimeHistory writes it
// ("disp_11_1"), or "" when the field names none. The node or element number
// may be an expression, "disp_n+1_1": the text between the first and the last
// underscore (the component is one digit), so that a parametrised deck names
// its columns the way its TPLOt records do.
std::string resolveColumn(const Record& rec, std::size_t i, const Parameters& params) {
  const std::string c = toLower(rec.text(i));
  for (const char* w : {"time", "prop", "arcl"})
    if (c == w) return c;
  for (const char* w : kEnergyColumns)
    if (c == w) return c;
  const auto first = c.find('_'), last = c.rfind('_');
  if (first != 4 || last <= first + 1 || last + 2 != c.size() || c.back() < '1' || c.back() > '3') return {};
  const std::string kind = c.substr(0, 4);
  if (kind != "disp" && kind != "velo" && kind != "acce" && kind != "reac" && kind != "stre") return {};
  const std::string number = rec.text(i).substr(first + 1, last - first - 1);
  SourceLoc at = rec[i].loc;
  at.col += static_cast<int>(first + 1);
  const int n = Expression::parse(number, at, rec.line).evalInt(params, "node or element number");
  return kind + "_" + std::to_string(n) + "_" + c.substr(last + 1);
}

std::vector<std::string> timeHistoryColumns(const Macro& tplot, const Parameters& params) {
  std::vector<std::string> cols = {"time", "prop"};
  for (const Record& rec : tplot.data) {
    const std::string k = commandKey(rec.text(0));
    if (k == "ener") {
      for (const char* e : kEnergyColumns) cols.push_back(e);
    } else if (k == "mome") {
      for (const char* e : kMomentumColumns) cols.push_back(e);
    } else if (k == "arcl") {
      cols.push_back("arcl");
    } else if (rec.size() >= 3) {
      const int n = Expression::parse(rec[1]).evalInt(params, "number");
      const int d = Expression::parse(rec[2]).evalInt(params, "component");
      cols.push_back(k + "_" + std::to_string(n) + "_" + std::to_string(d));
    }
  }
  return cols;
}

void checkPlotColumns(const std::vector<std::vector<Macro>>& batches, const Parameters& params) {
  std::vector<const Macro*> tplots, curves;
  for (const auto& b : batches) collect(b, tplots, curves);
  std::vector<std::string> known;
  for (const Macro* t : tplots)
    for (const std::string& c : timeHistoryColumns(*t, params)) known.push_back(c);
  for (const Macro* m : curves) {
    const Record& rec = m->data.front();
    if (tplots.empty())
      throw DeckError(m->record.fieldLoc(1), "PLOT,CURVe plots TPLOt columns, and this problem has no TPLOt",
                      m->record.excerpt(m->record.fieldLoc(1)), "add TPLOt with its records after END");
    for (std::size_t i = 0; i < 2; ++i) {
      const std::string c = resolveColumn(rec, i, params);
      if (std::find(known.begin(), known.end(), c) != known.end()) continue;
      std::string have;
      for (const std::string& k : known) have += (have.empty() ? "" : ", ") + k;
      const std::string named = c == toLower(rec.text(i)) ? c : rec.text(i) + "' = '" + c;
      failData(rec, i, "PLOT,CURVe: no TPLOt column '" + named + "'", "the TPLOt columns are " + have);
    }
  }
}

}  // namespace c2d
