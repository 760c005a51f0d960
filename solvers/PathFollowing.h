#pragma once
// Path following for static analysis: the load factor lambda multiplying FORCe
// becomes an unknown, fixed by a constraint per step (FEAP's ARCL).
//   kfl 4/5: displacement control: the displacement of one node dof grows by a
//            given increment per step (passes limit points in load);
//   kfl 1/2: arc-length (cylindrical, Crisfield): ||u - u_n|| = ds per step, the
//            arc length taken from the first step's load increment (passes
//            snap-backs).
// Each Newton iteration solves K du_R = R and K du_F = F_ref with the same
// factors, then du = du_R + dlambda du_F.
#include <Eigen/Core>
#include <istream>
#include <ostream>
#include <string>

#include "core/Error.h"

namespace c2d {

class PathFollowing {
 public:
  enum class Kind { DisplacementControl, ArcLength };

  static PathFollowing displacementControl(int equation, double increment);
  static PathFollowing arcLength(double firstLoadIncrement);

  Kind kind() const { return kind_; }
  int equation() const { return eq_; }
  void setEquation(int eq) { eq_ = eq; }

  void beginStep();  // called when time advances: the next iteration is a predictor
  // Fraction of the nominal step increment (displacement increment or arc length)
  // for the coming step: a located sub-step takes part of a step.
  void setStepScale(double s) { scale_ = s; }
  // Fraction of the nominal increment for every step from now on (step
  // cutting: dt / nominal dt), on top of the step scale.
  void setIncrementScale(double c) { cut_ = c; }
  double incrementScale() const { return cut_; }
  // Load-factor correction for this iteration. du (step increment so far, free dofs),
  // duR, duF: the two solutions. Returns the failure when no real root exists.
  Status correction(const Eigen::VectorXd& stepIncrement, const Eigen::VectorXd& duR,
                    const Eigen::VectorXd& duF, double& dlambda);
  void endStep(const Eigen::VectorXd& stepIncrement, double stepDlambda);  // at commit

  // Restart files (core/io/Checkpoint.h): the complete state as raw values.
  void write(std::ostream& out) const;
  static PathFollowing read(std::istream& in);  // throws CheckpointError

 private:
  Kind kind_ = Kind::DisplacementControl;
  int eq_ = -1;
  double increment_ = 0;      // displacement control
  double ds_ = 0;             // arc length (0: not yet known)
  double firstDlambda_ = 0;   // arc-length: load increment of the first step
  double lastDirection_ = 1;  // sign of the previous step's load increment
  Eigen::VectorXd lastIncrement_;
  bool predictor_ = true;
  double scale_ = 1.0;
  double cut_ = 1.0;
};

}  // namespace c2d
