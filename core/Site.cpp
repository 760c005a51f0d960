#include "core/Site.h"

namespace c2d {

const char* fallDirectionName(FallDirection d) {
  switch (d) {
    case FallDirection::Left: return "LEFT";
    case FallDirection::Right: return "RIGHT";
    case FallDirection::Down: return "DOWN";
    case FallDirection::None: break;
  }
  return "";
}

std::vector<ProtectedZone> protectedZones(const Site& site) {
  std::vector<ProtectedZone> zones;
  if (site.dir != FallDirection::Left) zones.push_back({"left", -kUnbounded, site.xmin, 0, 0});
  if (site.dir != FallDirection::Right) zones.push_back({"right", site.xmax, kUnbounded, 0, 0});
  zones.insert(zones.end(), site.objects.begin(), site.objects.end());
  return zones;
}

}  // namespace c2d
