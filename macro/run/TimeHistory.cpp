#include "macro/run/TimeHistory.h"

#include <cstdio>

#include "macro/deck/Expression.h"

namespace c2d {

TimeHistory::TimeHistory(std::filesystem::path path, std::vector<Column> columns, int every,
                         int tables)
    : file_(std::move(path)),
      columns_(std::move(columns)),
      every_(every < 1 ? 1 : every),
      tables_(tables < 1 ? 1 : tables) {
  header_ = {"time", "prop"};
  if (tables_ > 1)
    for (int k = 1; k <= tables_; ++k) header_.push_back("prop_" + std::to_string(k));
  for (const Column& c : columns_) {
    const std::string n = std::to_string(c.index + 1), d = std::to_string(c.component + 1);
    switch (c.kind) {
      case Kind::Disp: header_.push_back("disp_" + n + "_" + d); break;
      case Kind::Velo: header_.push_back("velo_" + n + "_" + d); break;
      case Kind::Acce: header_.push_back("acce_" + n + "_" + d); break;
      case Kind::Reac: header_.push_back("reac_" + n + "_" + d); break;
      case Kind::Stre: header_.push_back("stre_" + n + "_" + d); break;
      case Kind::Arcl: header_.push_back("arcl"); break;
      case Kind::Ener:
        for (const char* e : kEnergyColumns) header_.push_back(e);
        break;
      case Kind::Mome:
        for (const char* e : kMomentumColumns) header_.push_back(e);
        break;
    }
  }
  for (std::size_t i = 0; i < header_.size(); ++i) file_.stream() << (i ? "," : "") << header_[i];
  file_.stream() << '\n';
}

void TimeHistory::record(Analysis& analysis, bool force) {
  const State& s = analysis.state();
  if (s.step == lastStep_) return;
  if (!force && s.step % every_ != 0) return;
  lastStep_ = s.step;
  std::vector<double> row = {s.t, analysis.loadFactor()};
  if (tables_ > 1) {
    const double arc = analysis.pathFollowing() ? s.arcLambda : 1.0;
    for (int k = 1; k <= tables_; ++k) row.push_back(arc * analysis.tableFactor(k, s.t));
  }
  const Eigen::VectorXd& r = analysis.assembler().nodalResidual();
  bool energyDone = false;
  Energy en;
  for (const Column& c : columns_) {
    const Eigen::Index nd = static_cast<Eigen::Index>(c.index) * kNodeDofs + c.component;
    switch (c.kind) {
      case Kind::Disp: row.push_back(s.u[nd]); break;
      case Kind::Velo: row.push_back(s.v[nd]); break;
      case Kind::Acce: row.push_back(s.a[nd]); break;
      case Kind::Reac: row.push_back(nd < r.size() ? r[nd] : 0.0); break;
      case Kind::Stre: {
        // A removed element carries nothing.
        const Model& model = analysis.model();
        const SectionForces f =
            model.hasElement(c.index) ? model.element(c.index).sectionForces() : SectionForces{};
        row.push_back(c.component == 0 ? f.N : c.component == 1 ? f.V : f.M);
        break;
      }
      case Kind::Arcl: row.push_back(s.arcLambda); break;
      case Kind::Ener:
        if (!energyDone) en = analysis.energy();
        energyDone = true;
        for (double v : {en.kinetic, en.strain, en.contact, en.external, en.total(), en.dissipated,
                         en.balance()})
          row.push_back(v);
        break;
      case Kind::Mome: {
        const Assembler::Momentum p = analysis.assembler().momentum(s);
        for (double v : {p.linear.x(), p.linear.y(), p.angular}) row.push_back(v);
        break;
      }
    }
  }
  char buf[32];
  for (std::size_t i = 0; i < row.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%.10e", row[i] == 0 ? 0.0 : row[i]);
    file_.stream() << (i ? "," : "") << buf;
  }
  file_.stream() << '\n';
  rows_.push_back(std::move(row));
}

void TimeHistory::finish() {
  if (!file_.committed()) file_.commit();
}

std::vector<TimeHistory::Column> TimeHistory::columnsOf(const std::vector<Record>& data,
                                                      const Parameters& params,
                                                      const Model& model) {
  std::vector<Column> cols;
  for (const Record& rec : data) {
    const std::string k = commandKey(rec.text(0));
    TimeHistory::Column c{TimeHistory::Kind::Ener};
    if (k == "arcl") c.kind = TimeHistory::Kind::Arcl;
    if (k == "mome") c.kind = TimeHistory::Kind::Mome;
    if (k != "ener" && k != "arcl" && k != "mome") {
      c.kind = k == "disp"   ? TimeHistory::Kind::Disp
               : k == "velo" ? TimeHistory::Kind::Velo
               : k == "acce" ? TimeHistory::Kind::Acce
               : k == "reac" ? TimeHistory::Kind::Reac
                             : TimeHistory::Kind::Stre;
      c.index = Expression::parse(rec[1]).evalInt(params, "number") - 1;
      c.component = Expression::parse(rec[2]).evalInt(params, "component") - 1;
      const int limit =
          c.kind == TimeHistory::Kind::Stre ? model.numElements() : model.numNodes();
      if (c.index < 0 || c.index >= limit || c.component < 0 || c.component > 2)
        throw DeckError(rec[1].loc,
                        "TPLOt: no such " +
                            std::string(c.kind == TimeHistory::Kind::Stre ? "element" : "node") +
                            " or component",
                        rec.excerpt(rec[1].loc));
    }
    cols.push_back(c);
  }
  return cols;
}

}  // namespace c2d
