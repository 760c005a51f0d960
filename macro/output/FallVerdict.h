#pragma once
// Where a building went against where it was meant to go (SITE's dir): the
// verdict of a run from its mass centroid's move, and the figures beside it.
//
// A rigid body of height H and width W tipped a quarter turn about its back
// edge moves its centroid by (H - W)/2 toward the fall. Half of that counts:
// the threshold is T = max((H - W)/4, H/20) (a building about as wide as high
// does not tip as a body; a move below 5 % of its height stays "in place").
// With s the centroid's move, positive toward dir:
//   LEFT, RIGHT: felled when s >= T, other way when s <= -T, in place between;
//   DOWN:        in place (the intended outcome) when |s| < T, felled (it
//                toppled to a side) otherwise.
#include "core/Model.h"
#include "core/State.h"

namespace c2d {

enum class FallVerdict { None, Felled, InPlace, OtherWay };

// "felled", "in place", "other way"; "" for None.
const char* fallVerdictName(FallVerdict v);
// The threshold T above (m).
double fellingThreshold(double height, double width);
// The verdict for a centroid's move `shift` (+x) of a building of height H and
// width W meant to fall toward dir (None without a dir).
FallVerdict fallVerdict(FallDirection dir, double shift, double height, double width);
// The verdict is not the one dir intends (felled for LEFT/RIGHT, in place for DOWN).
bool unintended(FallDirection dir, FallVerdict v);

// The building's height: its highest node at the start over the ground line
// (GROUnd's y0; without ground, over its lowest node).
double buildingHeight(const Model& model);

// The largest tilt from the vertical of the part still standing (degrees,
// positive leaning toward +x): over the members vertical at the start (chord
// within 10 degrees of the vertical) that still rise by at least half their
// length (a member tilted past 60 degrees has fallen); 0 when none stands.
double standingTilt(const Model& model, const State& state);

}  // namespace c2d
