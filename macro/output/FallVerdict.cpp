#include "macro/output/FallVerdict.h"

#include <algorithm>
#include <cmath>

namespace c2d {

const char* fallVerdictName(FallVerdict v) {
  switch (v) {
    case FallVerdict::Felled: return "felled";
    case FallVerdict::InPlace: return "in place";
    case FallVerdict::OtherWay: return "other way";
    case FallVerdict::None: break;
  }
  return "";
}

double fellingThreshold(double height, double width) {
  return std::max((height - width) / 4, height / 20);
}

FallVerdict fallVerdict(FallDirection dir, double shift, double height, double width) {
  if (dir == FallDirection::None || !(height > 0)) return FallVerdict::None;
  const double t = fellingThreshold(height, width);
  if (dir == FallDirection::Down)
    return std::abs(shift) < t ? FallVerdict::InPlace : FallVerdict::Felled;
  const double s = dir == FallDirection::Right ? shift : -shift;
  return s >= t ? FallVerdict::Felled : s <= -t ? FallVerdict::OtherWay : FallVerdict::InPlace;
}

bool unintended(FallDirection dir, FallVerdict v) {
  if (dir == FallDirection::None || v == FallVerdict::None) return false;
  return dir == FallDirection::Down ? v != FallVerdict::InPlace : v != FallVerdict::Felled;
}

double buildingHeight(const Model& model) {
  bool any = false;
  double lo = 0, hi = 0;
  for (int n = 0; n < model.numNodes(); ++n) {
    if (!model.hasCoord(n)) continue;
    const double y = model.coord(n).y();
    lo = any ? std::min(lo, y) : y;
    hi = any ? std::max(hi, y) : y;
    any = true;
  }
  if (!any) return 0;
  const double base = model.ground() ? model.ground()->y0 : lo;
  return std::max(0.0, hi - base);
}

double standingTilt(const Model& model, const State& state) {
  const double kVertical = std::tan(10.0 * M_PI / 180.0);
  double tilt = 0;
  for (int e = 0; e < model.numElements(); ++e) {
    if (!model.hasElement(e)) continue;
    const auto n = model.element(e).nodes();
    Vec2 a0 = model.coord(n[0]), b0 = model.coord(n[1]);
    if (b0.y() < a0.y()) std::swap(a0, b0);
    const Vec2 d0 = b0 - a0;
    const double length = d0.norm();
    if (!(length > 0) || std::abs(d0.x()) > kVertical * d0.y()) continue;
    // The same ends now (lower end first as at the start).
    auto now = [&](int node) {
      const Eigen::Index i = static_cast<Eigen::Index>(node) * kNodeDofs;
      const Vec2 u = i + 1 < state.u.size() ? Vec2(state.u[i], state.u[i + 1]) : Vec2::Zero();
      return Vec2(model.coord(node) + u);
    };
    const bool flipped = model.coord(n[1]).y() < model.coord(n[0]).y();
    const Vec2 d = now(flipped ? n[0] : n[1]) - now(flipped ? n[1] : n[0]);
    if (d.y() < 0.5 * d.norm()) continue;
    const double deg = std::atan2(d.x(), d.y()) * 180.0 / M_PI;
    if (std::abs(deg) > std::abs(tilt)) tilt = deg;
  }
  return tilt;
}

}  // namespace c2d
