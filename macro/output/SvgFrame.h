#pragma once
// Picture of a frame model as standalone SVG 1.1: the undeformed mesh thin,
// gray and dashed, the deformed mesh solid (displacements times a scale
// factor), supports drawn from the restraint codes, joints as open circles,
// softening hinges as a red dot while active and a crossed circle once fully
// softened, the ground with hatching, a title, a scale bar and a key. One model
// length unit is the same number of pixels in x and y.
//
// Node positions are the coordinates plus State::u (node dof index node*3 + dof),
// so the state must hold every node's values, the slaves of condensed joints
// included (they are not in the global system and are filled in for output).
// Deformed members are cubic curves that leave each node at the node's rotation
// (Bezier control points at a third of the chord, which is the cubic Hermite
// shape for small rotations); an element with an active hinge is kinked at the
// hinge.
#include <filesystem>
#include <string>

#include "core/Model.h"
#include "core/State.h"

namespace c2d {

class SvgFrame {
 public:
  SvgFrame& setTitle(std::string title);               // e.g. "six-story frame, t = 1.25 s"
  SvgFrame& setDisplacementScale(double factor);       // default 1
  SvgFrame& setMaxSize(double width, double height);   // px; the picture fits inside (default 640 x 600)
  SvgFrame& setShowUndeformed(bool show);              // default true
  SvgFrame& setCurved(bool curved);                    // default true; false: straight chords
  SvgFrame& setScaleBar(bool show, std::string lengthUnit = "m");  // default shown, in m
  SvgFrame& setKey(bool show);                         // symbol key; default shown when symbols are
  SvgFrame& setShowNodes(bool show);                   // a dot at every node (the mesh); default false

  std::string svg(const Model& model, const State& state) const;
  void save(const std::filesystem::path& path, const Model& model, const State& state) const;

 private:
  std::string title_;
  double scale_ = 1;
  double maxWidth_ = 640, maxHeight_ = 600;
  bool undeformed_ = true, curved_ = true, scaleBar_ = true, key_ = true, nodes_ = false;
  std::string unit_ = "m";
};

}  // namespace c2d
