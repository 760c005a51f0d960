#pragma once
// Results for ParaView: one VTK XML UnstructuredGrid file (.vtu, ASCII) per
// output step plus a .pvd collection listing every step with its time, so that
// ParaView plays a collapse as an animation.
//
// Points are the deformed node positions (x + u, y + v, 0); cells are one
// VTK_LINE per element (its two nodes). Point data: displacement (u, v, 0),
// rotation, velocity (du/dt, dv/dt, 0), joint (1 for a joint master or slave).
// Cell data: N, V, M (Element::sectionForces(): axial tension +, shear, bending
// counterclockwise on the positive face), material, hinge_state (0 none, 1
// active, 2 fully softened), hinge_jump (rad), hinge_position (s_d / l_e).
// Nodal values come from the trial state (State::u, State::v), which equals the
// committed one after a converged step; the slaves of condensed joints, which
// are not in the global system, must have been filled in for output.
//
// Every file is written atomically (core/io/AtomicFile.h). The collection is
// rewritten as "<stem>.pvd.part" after each .vtu is complete (it only ever lists
// complete steps and can be opened while the run goes on) and becomes
// "<stem>.pvd" only when the run completes (finish()); a failed or interrupted
// run keeps it as "<stem>.failed.pvd" or "<stem>.interrupted.pvd" (keep()).
// Times are printed with 12 significant digits: a time reached by adding steps
// reads as the deck's numbers (0.3, not 0.30000000000000004).
#include <filesystem>
#include <string>

#include "core/io/AtomicFile.h"
#include "core/Model.h"
#include "core/State.h"

namespace c2d {

class VtkWriter {
 public:
  // Files "<stem>_0000.vtu", "<stem>_0001.vtu", ... and "<stem>.pvd".
  explicit VtkWriter(std::filesystem::path stem);

  // Writes the next step and updates the collection; returns the .vtu path.
  std::filesystem::path write(const Model& model, const State& state, double time);
  // The run completed: the collection becomes "<stem>.pvd".
  void finish() { pvd_.close(); }
  // The run failed or was interrupted: the collection under its tagged name.
  std::filesystem::path keep(std::string_view tag) { return pvd_.keep(tag); }
  int numWritten() const { return count_; }
  std::filesystem::path collectionPath() const;
  std::filesystem::path stepPath(int step) const;

  // The text of one .vtu file.
  static std::string unstructuredGrid(const Model& model, const State& state);
  // A time as the collection prints it.
  static std::string timeText(double t);

 private:
  std::filesystem::path stem_;
  int count_ = 0;
  AtomicAppendFile pvd_;
};

}  // namespace c2d
