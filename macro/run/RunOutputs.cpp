#include "macro/run/RunOutputs.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "macro/output/SvgChart.h"
#include "macro/output/SvgFrame.h"
#include "macro/output/NumberText.h"

namespace c2d {

namespace {

std::string shortNumber(double v) { return formatNumber("%.4g", v == 0 ? 0.0 : v); }

// Extent of the drawn model: the larger side of the bounding box of the nodes
// that carry elements.
double modelExtent(const Model& model) {
  double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
  for (const auto& el : model.elements()) {
    if (!el) continue;
    for (int n : el->nodes()) {
      if (n < 0 || n >= model.numNodes()) continue;
      const Vec2& x = model.coord(n);
      xmin = std::min(xmin, x.x());
      xmax = std::max(xmax, x.x());
      ymin = std::min(ymin, x.y());
      ymax = std::max(ymax, x.y());
    }
  }
  return xmax >= xmin ? std::max(xmax - xmin, ymax - ymin) : 0.0;
}

}  // namespace

RunOutputs::RunOutputs(std::filesystem::path outDir, std::string stem, std::string title,
                       std::string label)
    : outDir_(std::move(outDir)), stem_(std::move(stem)), title_(std::move(title)),
      label_(std::move(label)) {}

std::string RunOutputs::displayTitle(const std::string& feapTitle) {
  std::size_t p = 0;
  while (p < feapTitle.size() && (feapTitle[p] == '*' || feapTitle[p] == ' ')) ++p;
  std::string t = feapTitle.substr(p);
  while (!t.empty() && t.back() == ' ') t.pop_back();
  return t;
}

std::string RunOutputs::heading() const {
  std::string h = displayTitle(title_);
  if (!label_.empty()) h += h.empty() ? label_ : " (" + label_ + ")";
  return h;
}

std::filesystem::path RunOutputs::plotMesh(const Model& model) const {
  // The reference configuration: no displacements at all.
  const State reference;
  const std::filesystem::path path = file("_mesh.svg");
  if (!pictures_) return path;
  SvgFrame().setTitle(heading()).setShowUndeformed(false).setShowNodes(true).save(path, model, reference);
  return path;
}

double RunOutputs::automaticScale(const Model& model, const State& state) {
  double umax = 0;
  for (int n = 0; n < model.numNodes(); ++n) {
    const Eigen::Index i = static_cast<Eigen::Index>(n) * kNodeDofs;
    if (i + 1 >= state.u.size()) break;
    umax = std::max(umax, std::hypot(state.u[i], state.u[i + 1]));
  }
  const double extent = modelExtent(model);
  if (!(umax > 0) || !(extent > 0) || umax >= 0.05 * extent) return 1;
  return std::max(1.0, SvgChart::niceNumber(0.1 * extent / umax, true));
}

std::optional<std::filesystem::path> RunOutputs::plotDeformed(const Model& model,
                                                              const State& state, double scale,
                                                              bool curved) {
  // The step being computed: once TIME has advanced past the last committed
  // step, a converged state belongs to the next one (the log counts the same way).
  const int step = state.step + (state.t > state.tn ? 1 : 0);
  if (step == lastPicture_.step && state.t == lastPicture_.t && scale == lastPicture_.scale &&
      curved == lastPicture_.curved) {
    ++lastPicture_.skipped;
    return std::nullopt;
  }
  const double asked = scale;
  if (!(scale > 0) && !(scale < 0)) scale = automaticScale(model, state);
  char name[48];
  std::snprintf(name, sizeof name, "_deformed_%04d.svg", step);
  const std::filesystem::path path = file(name);
  std::string t = heading();
  t += (t.empty() ? "" : ": ") + std::string("step ") + std::to_string(step) + ", t = " +
       shortNumber(state.t);
  if (!pictures_) return path;
  SvgFrame().setTitle(t).setDisplacementScale(scale).setCurved(curved).save(path, model, state);
  lastPicture_ = {path, step, state.t, asked, curved, 0};
  return path;
}

std::vector<std::pair<double, double>> RunOutputs::curvePoints(const CurveSpec& spec,
                                                               const TimeHistory& history) {
  const auto& h = history.header();
  const auto ix = std::find(h.begin(), h.end(), spec.xColumn);
  const auto iy = std::find(h.begin(), h.end(), spec.yColumn);
  std::vector<std::pair<double, double>> pts;
  if (ix == h.end() || iy == h.end()) return pts;
  const auto cx = static_cast<std::size_t>(ix - h.begin()), cy = static_cast<std::size_t>(iy - h.begin());
  for (const auto& row : history.rows())
    if (cx < row.size() && cy < row.size()) pts.emplace_back(spec.xScale * row[cx], spec.yScale * row[cy]);
  return pts;
}

std::string RunOutputs::curveSvg(
    const std::string& title, const CurveSpec& spec,
    const std::vector<std::pair<std::string, std::vector<std::pair<double, double>>>>& series) {
  SvgChart chart;
  chart.setTitle(title).setXLabel(spec.xLabel).setYLabel(spec.yLabel);
  for (const auto& [name, pts] : series) {
    SeriesStyle style;
    // A lone curve of a few points reads better with its points marked.
    style.markers = series.size() == 1 && pts.size() <= 12;
    chart.addSeries(name, pts, style);
  }
  return chart.svg();
}

std::optional<std::filesystem::path> RunOutputs::plotCurve(const CurveSpec& spec,
                                                           const TimeHistory* history) {
  if (std::none_of(curves_.begin(), curves_.end(), [&](const CurveSpec& c) { return c.sameAs(spec); }))
    curves_.push_back(spec);
  if (!history) return std::nullopt;
  const std::filesystem::path path = file('_' + spec.fileName() + ".svg");
  if (!pictures_) return path;
  AtomicFile::write(path, curveSvg(heading(), spec, {{std::string(), curvePoints(spec, *history)}}));
  return path;
}

std::vector<CurveData> RunOutputs::curves(const TimeHistory* history) const {
  std::vector<CurveData> out;
  for (const CurveSpec& c : curves_)
    out.push_back({c, history ? curvePoints(c, *history) : std::vector<std::pair<double, double>>{}});
  return out;
}

std::optional<std::filesystem::path> RunOutputs::writeView(const Model& model, const State& state) {
  if (!pictures_) return std::nullopt;
  if (vtk_ && state.step == lastViewStep_ && state.t == lastViewTime_) return std::nullopt;
  if (!vtk_) vtk_ = std::make_unique<VtkWriter>(outDir_ / stem_);
  lastViewStep_ = state.step;
  lastViewTime_ = state.t;
  return vtk_->write(model, state, state.t);
}

void RunOutputs::onCommit(const Model& model, const State& state) {
  if (viewEvery_ > 0 && state.step % viewEvery_ == 0) writeView(model, state);
}

void RunOutputs::finish(const Model& model, const State& state, const TimeHistory* history) {
  if (viewEvery_ > 0) writeView(model, state);
  if (vtk_) vtk_->finish();
  if (!history) return;
  for (const CurveSpec& c : curves_) plotCurve(c, history);
}

std::vector<std::filesystem::path> RunOutputs::keep(std::string_view tag) {
  std::vector<std::filesystem::path> kept;
  if (vtk_ && vtk_->numWritten() > 0) kept.push_back(vtk_->keep(tag));
  return kept;
}

}  // namespace c2d
