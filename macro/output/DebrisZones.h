#pragma once
// The debris in the site's protected zones (core/Site.h), and the flying
// fragments apart from the debris bed.
//
// A piece is a set of members connected through their nodes and joints (with
// the nodal masses at its nodes, macro/output/Debris.h pieceMassAtNodes). Pieces
// lighter than the flyrock limit (SITE's FLYRock, default kFlyrockShare of the
// building's mass) are flying fragments; the rest is the debris bed. A zone
// holds the mass lying in x1 <= x <= x2 at or above its height over the ground
// (a member's mass spread along its chord, a nodal mass at its node); the bed
// hits the zone when its mass there exceeds the zone's allowance.
#include <string>
#include <vector>

#include "core/Model.h"
#include "core/State.h"

namespace c2d {

struct ZoneFigures {
  std::string name;
  double x1 = 0, x2 = 0;  // where it lies (a side: unbounded outward)
  double mass = 0;     // the bed's mass in the zone
  bool hit = false;    // mass > the zone's allowance
  double heaviest = 0; // the heaviest piece (bed or fragment) with mass in the zone, 0: none
  int flyrockCount = 0;     // flying fragments with mass in the zone
  double flyrockMass = 0;   // their mass in the zone
};

// The flyrock limit (t) of a site for a building of total mass `total`.
double flyrockLimit(const Site& site, double total);

// The share of the segment a-b inside x1 <= x <= x2, y >= ymin (0..1; a point
// when a == b: 1 inside, 0 outside).
double shareInZone(const Vec2& a, const Vec2& b, double x1, double x2, double ymin);

// Every protected zone's figures (protectedZones(site) order) at the state,
// fragments being the pieces lighter than `limit`.
std::vector<ZoneFigures> zoneFigures(const Model& model, const State& state, const Site& site,
                                     double limit);

}  // namespace c2d
