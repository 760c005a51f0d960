#include "macro/run/EnergyWatch.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/io/Checkpoint.h"

namespace c2d {

void EnergyWatch::onCommit(const Energy& en, bool dynamic, int step, double t) {
  const double scale = std::abs(en.kinetic) + std::abs(en.strain) + std::abs(en.contact) +
                       std::abs(en.external) + std::abs(en.dissipated);
  if (!started_) {
    energy0_ = en.balance();
    dissipatedN_ = en.dissipated;
    restoredN_ = en.restored;
    stored0_ = std::abs(en.kinetic) + std::abs(en.strain) + std::abs(en.contact);
    started_ = true;
  }
  input_ = std::max(input_, stored0_ + std::abs(en.external));
  scale_ = std::max(scale_, scale);
  if (scale_ > 0) error_ = std::max(error_, std::abs(en.balance() - energy0_) / scale_);
  // A fall of the dissipation that the contacts restored is no gain.
  const double gain = dissipatedN_ - en.dissipated - (en.restored - restoredN_);
  dissipatedN_ = en.dissipated;
  restoredN_ = en.restored;
  if (!dynamic || !(gain > 0)) return;
  gained_ += gain;
  if (gainStep_ == 0 && gained_ > kGainTolerance * input_) {
    gainStep_ = step;
    gainTime_ = t;
  }
}

void EnergyWatch::save(std::ostream& out) const {
  using namespace checkpoint;
  putBool(out, started_);
  for (double x : {energy0_, scale_, error_, stored0_, input_, dissipatedN_, restoredN_, gained_,
                   gainTime_})
    put(out, x);
  put(out, gainStep_);
}

void EnergyWatch::load(std::istream& in) {
  using namespace checkpoint;
  started_ = getBool(in);
  for (double* x :
       {&energy0_, &scale_, &error_, &stored0_, &input_, &dissipatedN_, &restoredN_, &gained_,
        &gainTime_})
    *x = get<double>(in);
  gainStep_ = get<int>(in);
}

std::string energyGainText(double gained, int step, double t) {
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "the motion gained %.2e of the energy put in without work (%.0e of it by step %d, "
                "t = %.6e): the time integrator created it, as Newmark's rule does with "
                "nonlinear members; DYNAmic,ENERgy conserves or decays the energy",
                gained, EnergyWatch::kGainTolerance, step, t);
  return buf;
}

}  // namespace c2d
