#pragma once
// Output at times the steps do not land on: the motion between the committed
// state at t_n and the converged state at t_n+1, sampled at a scheduled time
// (a picture loop's TIME,,tmax that its last step passed: macro/run/RunCursor.h),
// so that pictures and ParaView frames come at the times the deck asks for
// without a step ending there.
//
// The sample at t in [t_n, t_n+1], s = (t - t_n)/h, h = t_n+1 - t_n: in a
// dynamic analysis every nodal value (translations and rotations alike: a
// plane rotation is a number that adds) follows the cubic Hermite
// interpolant of the two states' displacements and velocities,
//   u(s) = H00 u_n + H10 h v_n + H01 u_n+1 + H11 h v_n+1,
// its derivative the velocity, the acceleration linear between a_n and
// a_n+1; under the energy conserving scheme, (u_n+1 - u_n)/h = (v_n + v_n+1)/2,
// it is the motion of constant acceleration (v_n+1 - v_n)/h. In statics
// (pseudo-time, no rates) all values are linear in s, as the load factor.
// Joints' slave nodes are filled in at both ends first, so a joint's relative
// rotation is interpolated like the rest. What the elements report (section
// forces, hinges, joints) is theirs at t_n+1: the sample moves no element.
#include <optional>
#include <vector>

#include "core/Model.h"
#include "core/State.h"
#include "solvers/TimeIntegrator.h"

namespace c2d {

// The state at time t (clamped to [t_n, t_n+1]) as above, labelled t; the
// committed part (t_n values, contact memories) is the state's.
State denseState(const State& state, double t, const TimeIntegrator& integrator);

// What outputs show: the state itself, or its sample at a scheduled time
// while the state is the one the time was scheduled in (no step, commit or
// return since).
class DenseOutput {
 public:
  // The converged step ends past `t` (the loop's tmax): outputs show the
  // motion at t, or at t_n when a located event committed the step past t.
  // Nothing to schedule when the step ends on t.
  void schedule(const State& state, double t);
  // The state for an output, slave nodes filled in (which changes only the
  // state's slave nodes, as a commit does).
  const State& outputState(const Model& model, State& state, const TimeIntegrator& integrator);
  // The scheduled time, while it applies to `state`.
  std::optional<double> scheduled(const State& state) const;

  // A step taken in parts (solvers/ImpactSteps.h) commits each part: a time
  // scheduled within an earlier part than the last is sampled between the
  // committed states that bracket it. stepBegins() with the state a step
  // starts from, partCommitted() after each part's commit.
  void stepBegins(const State& state);
  void partCommitted(const State& state);

 private:
  struct Committed {
    double t = 0, prop = 0, arcLambda = 0;
    Eigen::VectorXd u, v, a;
  };
  static Committed committed(const State& state);

  std::optional<double> time_;
  double t_ = 0, tn_ = 0;  // the state it was scheduled in
  int step_ = 0;
  std::optional<State> sample_;  // made at the first output
  std::vector<Committed> parts_;   // the step's start and its parts' commits
  std::optional<State> bracket_;   // the part that holds the scheduled time
};

}  // namespace c2d
