#pragma once
// The site of a demolition (SITE): the zone x in [xmin, xmax] the debris must
// stay in, the intended fall and the protected zones around it. Units are the
// deck's (m, t).
#include <limits>
#include <string>
#include <vector>

namespace c2d {

// Where the building is meant to go: felled toward a side, or imploded in place.
enum class FallDirection { None, Left, Right, Down };

// A protected object: debris must not lie in x in [x1, x2] at or above height
// `height` over the ground (0: at any height), beyond `mass` (t, 0: none).
// The site's sides are zones too ("left": x < xmin, "right": x > xmax) unless
// the intended fall names that side as the one receiving the debris.
struct ProtectedZone {
  std::string name;
  double x1 = 0, x2 = 0;
  double height = 0, mass = 0;
};

struct Site {
  double xmin = 0, xmax = 0;
  FallDirection dir = FallDirection::None;
  std::vector<ProtectedZone> objects = {};  // the deck's named zones, in deck order
  // Pieces lighter than this (t) are flying fragments, counted apart from the
  // debris bed; negative: kFlyrockShare of the building's mass.
  double flyrockMass = -1;
  // The risk a study must show each protected zone's probability below, and
  // the confidence it must do so with (the exact binomial bound).
  double riskLevel = 0.01, riskConfidence = 0.95;
};

// The default flyrock limit as a share of the building's mass.
inline constexpr double kFlyrockShare = 0.01;

// "LEFT", "RIGHT", "DOWN", "" (None).
const char* fallDirectionName(FallDirection d);

// Every zone the site protects, sides first ("left" unless dir is Left, "right"
// unless dir is Right, unbounded outward), then the deck's objects.
std::vector<ProtectedZone> protectedZones(const Site& site);

inline constexpr double kUnbounded = std::numeric_limits<double>::infinity();

}  // namespace c2d
