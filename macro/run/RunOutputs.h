#pragma once
// The result files people look at, for one run: pictures of the frame
// (PLOT,MESH and PLOT,DEFOrmed, SVG), x-y charts of time-history columns
// (PLOT,CURVe, SVG) and the ParaView collection (PVIEw, .vtu per output +
// .pvd). Every file name starts with the run's stem:
//   <stem>_mesh.svg   <stem>_deformed_0042.svg (step 42)
//   <stem>_<y>_vs_<x>.svg (TPLOt column names)   <stem>_0000.vtu ... <stem>.pvd
// Nodal pictures need every node's values, the slaves of condensed joints
// included: the states given are filled in (syncSlaveNodes, as
// ProblemRun::outputState and every commit do).
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/Model.h"
#include "core/State.h"
#include "macro/output/VtkWriter.h"
#include "macro/run/TimeHistory.h"

namespace c2d {

// One PLOT,CURVe: y against x, both TPLOt columns, each times its scale
// (sx = -1 plots a reaction as the load it balances).
struct CurveSpec {
  std::string xColumn, yColumn;  // "disp_10_1", "reac_10_1", "time", "prop", "total", ...
  std::string xLabel, yLabel;    // axis labels as printed
  double xScale = 1, yScale = 1;
  // The columns as the deck writes them ("disp_n+1_3"): the runs of a mesh study
  // plot the same quantity under other node numbers.
  std::string written;

  // "<y>_vs_<x>": the file name after the stem.
  std::string fileName() const { return yColumn + "_vs_" + xColumn; }
  // The same picture (overlays join those): the same columns as written, labels
  // and scales.
  bool sameAs(const CurveSpec& o) const {
    return written == o.written && xLabel == o.xLabel && yLabel == o.yLabel &&
           xScale == o.xScale && yScale == o.yScale;
  }
};

struct CurveData {
  CurveSpec spec;
  std::vector<std::pair<double, double>> points;
};

class RunOutputs {
 public:
  // title: the problem's title; label: what tells this run apart (sweep values), or "".
  RunOutputs(std::filesystem::path outDir, std::string stem, std::string title, std::string label);

  // Off: no picture and no ParaView file is written (the methods still say
  // which file they stand for); the curves are kept for the overlays.
  void setPictures(bool on) { pictures_ = on; }

  // PLOT,MESH: the undeformed mesh with supports and joints.
  std::filesystem::path plotMesh(const Model& model) const;
  // PLOT,DEFOrmed: the deformed shape; scale 0 chooses one (automaticScale);
  // curved: members leave each node at its rotation (else straight chords).
  // Nothing when the last picture drew the same state (step and time) the same
  // way: a picture loop after the motion has come to rest.
  std::optional<std::filesystem::path> plotDeformed(const Model& model, const State& state,
                                                    double scale, bool curved = true);
  // The last deformed shape drawn, and how many pictures of its state were
  // skipped since.
  const std::filesystem::path& lastDeformed() const { return lastPicture_.path; }
  int deformedSkipped() const { return lastPicture_.skipped; }
  // PLOT,CURVe: remembers the curve (finish() writes it again, complete) and
  // writes it now from the history so far; nothing now without a history.
  std::optional<std::filesystem::path> plotCurve(const CurveSpec& spec, const TimeHistory* history);

  // PVIEw: writes the current state as the next .vtu of the collection;
  // nothing when that state (same step and time) was the last one written.
  std::optional<std::filesystem::path> writeView(const Model& model, const State& state);
  // Automatic PVIEw output every `every` committed steps (0: off).
  void setViewInterval(int every) { viewEvery_ = every < 0 ? 0 : every; }
  int viewInterval() const { return viewEvery_; }
  int viewsWritten() const { return vtk_ ? vtk_->numWritten() : 0; }

  // After each committed step (automatic PVIEw output).
  void onCommit(const Model& model, const State& state);
  // End of a run that completed: every curve written again from the whole
  // history; with automatic PVIEw output on, the final state is the last .vtu
  // (whatever the interval); the collection becomes <stem>.pvd.
  void finish(const Model& model, const State& state, const TimeHistory* history);
  // A run that failed or was interrupted: the collection so far kept under its
  // tagged name (<stem>.failed.pvd). Returns the files kept.
  std::vector<std::filesystem::path> keep(std::string_view tag);

  // The curves of this run as last written (for the overlays of a parameter study).
  std::vector<CurveData> curves(const TimeHistory* history) const;
  const std::string& title() const { return title_; }
  const std::string& label() const { return label_; }

  // Displacement factor that makes a small deformation visible: 1 when the
  // largest nodal displacement is already 5 % of the model's extent or more (or
  // zero), otherwise a 1-2-5 number that draws it at about a tenth of the extent.
  static double automaticScale(const Model& model, const State& state);
  // A curve's points from a history; empty when a column is missing.
  static std::vector<std::pair<double, double>> curvePoints(const CurveSpec& spec,
                                                            const TimeHistory& history);
  // The chart of one or several runs' curves (names: legend entries, may be empty).
  static std::string curveSvg(const std::string& title, const CurveSpec& spec,
                              const std::vector<std::pair<std::string, std::vector<std::pair<double, double>>>>& series);
  // The title as drawn: FEAP's leading "* *" markers and blanks removed.
  static std::string displayTitle(const std::string& feapTitle);

 private:
  std::filesystem::path file(const std::string& suffix) const { return outDir_ / (stem_ + suffix); }
  std::string heading() const;

  std::filesystem::path outDir_;
  std::string stem_, title_, label_;
  std::vector<CurveSpec> curves_;
  std::unique_ptr<VtkWriter> vtk_;
  int viewEvery_ = 0;
  bool pictures_ = true;
  int lastViewStep_ = -1;  // the state last written, so that PVIEw and the interval never repeat it
  double lastViewTime_ = 0;
  struct Picture {
    std::filesystem::path path;
    int step = -1;
    double t = 0, scale = 0;
    bool curved = true;
    int skipped = 0;
  } lastPicture_;
};

}  // namespace c2d
