#include "solvers/PathFollowing.h"

#include <cmath>

#include "core/io/Checkpoint.h"

namespace c2d {

PathFollowing PathFollowing::displacementControl(int equation, double increment) {
  PathFollowing p;
  p.kind_ = Kind::DisplacementControl;
  p.eq_ = equation;
  p.increment_ = increment;
  return p;
}

PathFollowing PathFollowing::arcLength(double firstLoadIncrement) {
  PathFollowing p;
  p.kind_ = Kind::ArcLength;
  p.firstDlambda_ = firstLoadIncrement;
  return p;
}

void PathFollowing::beginStep() { predictor_ = true; }

Status PathFollowing::correction(const Eigen::VectorXd& stepIncrement, const Eigen::VectorXd& duR,
                                 const Eigen::VectorXd& duF, double& dlambda) {
  const bool predictor = predictor_;
  predictor_ = false;
  const double scale = scale_ * cut_;
  if (kind_ == Kind::DisplacementControl) {
    if (eq_ < 0) return Status::failure("the controlled dof is not a free equation");
    const double target = predictor ? scale * increment_ : scale * increment_ - stepIncrement[eq_];
    if (std::abs(duF[eq_]) < 1e-300)
      return Status::failure("the load does not move the controlled dof (zero stiffness coupling)");
    dlambda = (target - duR[eq_]) / duF[eq_];
    return Status::success();
  }
  // Cylindrical arc length.
  if (predictor) {
    if (ds_ == 0) {
      // The nominal arc length is the first step's; a cut first step takes its part.
      dlambda = cut_ * firstDlambda_;
      ds_ = std::abs(firstDlambda_) * duF.norm();
      if (ds_ == 0) return Status::failure("arc length: zero load pattern response");
      return Status::success();
    }
    double sign = lastDirection_;
    if (lastIncrement_.size() == duF.size()) sign = lastIncrement_.dot(duF) >= 0 ? 1.0 : -1.0;
    dlambda = sign * scale * ds_ / duF.norm();
    return Status::success();
  }
  // ||a + dlambda duF||^2 = ds^2 with a = stepIncrement + duR
  const Eigen::VectorXd& s = stepIncrement;
  const double A = duF.squaredNorm();
  const double B = 2.0 * (s + duR).dot(duF);
  const double C = (s + duR).squaredNorm() - scale * scale * ds_ * ds_;
  const double disc = B * B - 4 * A * C;
  if (disc < 0) {
    // No real root: take the closest point (minimum of the quadratic), a common remedy.
    dlambda = -B / (2 * A);
    return Status::success();
  }
  const double r1 = (-B + std::sqrt(disc)) / (2 * A);
  const double r2 = (-B - std::sqrt(disc)) / (2 * A);
  // The root whose increment keeps the smallest angle with the current step increment.
  const double c1 = (s + duR + r1 * duF).dot(s);
  const double c2 = (s + duR + r2 * duF).dot(s);
  dlambda = c1 >= c2 ? r1 : r2;
  return Status::success();
}

void PathFollowing::endStep(const Eigen::VectorXd& stepIncrement, double stepDlambda) {
  lastIncrement_ = stepIncrement;
  if (stepDlambda != 0) lastDirection_ = stepDlambda > 0 ? 1.0 : -1.0;
}

void PathFollowing::write(std::ostream& out) const {
  using namespace checkpoint;
  put(out, kind_);
  put(out, eq_);
  for (double x : {increment_, ds_, firstDlambda_, lastDirection_, scale_, cut_}) put(out, x);
  putVector(out, lastIncrement_);
  putBool(out, predictor_);
}

PathFollowing PathFollowing::read(std::istream& in) {
  using namespace checkpoint;
  PathFollowing p;
  p.kind_ = get<Kind>(in);
  if (p.kind_ != Kind::DisplacementControl && p.kind_ != Kind::ArcLength)
    throw CheckpointError("unknown path following kind");
  p.eq_ = get<int>(in);
  for (double* x : {&p.increment_, &p.ds_, &p.firstDlambda_, &p.lastDirection_, &p.scale_, &p.cut_})
    *x = get<double>(in);
  p.lastIncrement_ = getVector(in);
  p.predictor_ = getBool(in);
  return p;
}

}  // namespace c2d
