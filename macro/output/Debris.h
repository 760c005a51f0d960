#pragma once
// Where the debris of a collapse ends up, judged against the site (SITE): the
// figures of the debris CSV, the log, the plans table and PLOT,DEBRis.
//
// Units are the deck's (the paper's decks: m, t, kN, s). The footprint is the
// x-extent of the nodes in the reference configuration. Masses "lie where they
// are": an element's translational mass (and the floor mass it carries, QLOAd
// MASS) is spread uniformly along its current chord, a nodal mass (MASS) sits
// at its node. The ground force is the penalty force k <y0 - y> summed over
// the nodes at the given state (the elastic part of the contact force).
#include <optional>
#include <string>
#include <vector>

#include "macro/output/DebrisZones.h"
#include "core/DofMap.h"
#include "macro/output/FallVerdict.h"
#include "core/Model.h"
#include "core/State.h"

namespace c2d {

// Mass spread uniformly over x in [x0, x1] (x0 == x1: a point mass); y0, y1:
// the heights of its ends at x0 and x1; node: a node of the piece it belongs to.
struct MassPiece {
  double x0 = 0, x1 = 0, mass = 0;
  double y0 = 0, y1 = 0;
  int node = -1;
};

struct DebrisFigures {
  double footprintMin = 0, footprintMax = 0;  // x-extent of the nodes at the start
  double xmin = 0, xmax = 0;                  // x-extent of the nodes now
  int leftNode = -1, rightNode = -1;          // the nodes at xmin, xmax (0-based)
  double left = 0, right = 0;                 // beyond the footprint on each side, >= 0
  double height = 0;                          // highest point now
  double totalMass = 0, outsideMass = 0;      // outside: 0 without a site
  std::optional<Site> site;
  double peakGroundForce = 0, peakTime = 0;  // largest total ground force over the run
  // The node that went deepest into the ground over the run (-1: none touched
  // it), how deep (y0 - y) and when, and half the section depth of its members
  // (0: they give no section), deeper than which it lies buried in the pictures.
  int deepestNode = -1;
  double deepest = 0, deepestTime = 0, deepestLimit = 0;
  // Robust figures of where the mass lies (a chaotic collapse moves the
  // furthest point by metres with one thrown piece; these move little):
  // the x of the mass centroid now and its shift since the start (the same
  // mass at its reference positions); how far beyond the footprint's edges the
  // debris reaches once the outermost 5 % of its mass on that side is left out
  // (0 inside). leftPieceMass, rightPieceMass: the mass of the piece (members
  // connected through their nodes and joints, with their nodal masses) that
  // holds the node at xmin, xmax.
  double centroid = 0, centroidShift = 0, left95 = 0, right95 = 0;
  double leftPieceMass = 0, rightPieceMass = 0;
  // The heaviest piece with a node beyond the 95 % reaches on either side
  // (0: none): what the robust figures leave out, thrown or flying, and
  // whether it is a fragment or a storey.
  double heaviestBeyond95 = 0;
  // The x-intervals [x0, x1] that debris occupies now (the union of the
  // members' chords and the nodal masses' points), left to right.
  std::vector<std::pair<double, double>> cover;
  // The kinetic energy at the end over its peak in the run's dynamic analysis
  // (0 in a static run), and the ratio at or below which the debris is at rest
  // (TIME,REST's, else its default): the caller's to fill.
  double kineticRatio = 0, restRatio = 1e-5;
  // Where the building went (macro/output/FallVerdict.h): its height H at the start,
  // the largest tilt of what still stands (degrees, + toward +x) and the
  // verdict against the site's intended fall (None without a dir).
  double buildingHeight = 0, tilt = 0;
  FallVerdict verdict = FallVerdict::None;
  // With a site: the flyrock limit (t), the flying fragments (pieces lighter
  // than it, macro/output/DebrisZones.h) and their mass, and every protected zone's
  // figures. The reaches, the centroid, the 95 % reaches and the mass outside
  // are the bed's (without the fragments); totalMass and cover are everything's.
  double flyrockLimit = 0, flyrockMass = 0;
  int flyrockCount = 0;
  std::vector<ZoneFigures> zones = {};

  // Some node lies outside the site (false without one).
  bool outside() const;
  // "none", "inside" or "outside".
  std::string siteStatus() const;
  // A node went deeper into the ground than half its members' section depth:
  // the ground's penalty is too soft for the impact.
  bool sunk() const { return deepestLimit > 0 && deepest > deepestLimit; }
  // The debris has come to rest: its figures are final.
  bool atRest() const { return kineticRatio <= restRatio; }
  // The centroid's move in the building's height (0 without a height).
  double centroidMoveH() const { return buildingHeight > 0 ? centroidShift / buildingHeight : 0; }
  // The site gives a dir and the verdict is not the intended one.
  bool unintendedFall() const;
};

// The figures of the state (peakGroundForce/peakTime are the caller's to fill).
DebrisFigures debrisFigures(const Model& model, const State& state);

// Every element's and node's mass where it lies now.
std::vector<MassPiece> massPieces(const Model& model, const State& state);
// The part of the pieces' mass outside [site.xmin, site.xmax].
double massOutside(const std::vector<MassPiece>& pieces, const Site& site);
// The x below which the share q (0..1) of the pieces' mass lies (each piece
// spread uniformly over its interval, a point mass at its point).
double massQuantile(const std::vector<MassPiece>& pieces, double q);
// The union of the pieces' intervals, left to right.
std::vector<std::pair<double, double>> massCover(const std::vector<MassPiece>& pieces);
// The mass of the piece holding each node: members connected through shared
// nodes and joints, with the nodal masses at their nodes (0 for a node no
// element holds).
std::vector<double> pieceMassAtNodes(const Model& model);
// The piece each node belongs to, as the number of one of its nodes (0-based).
std::vector<int> pieceOfNodes(const Model& model);
// Mass per bin of width `width` from x = x0 (bins values; a piece counts in
// proportion to its overlap with each bin).
std::vector<double> massHistogram(const std::vector<MassPiece>& pieces, double x0, double width,
                                  int bins);

// Total ground contact force at the state's positions (0 without ground).
double groundForce(const Model& model, const DofMap& dofs, const State& state);

// The node deepest in the ground at the state's positions and its depth y0 - y
// (node -1 when no node is below the ground line, or without ground).
struct GroundDepth {
  int node = -1;
  double depth = 0;
};
GroundDepth deepestNode(const Model& model, const DofMap& dofs, const State& state);
// Half the section depth of the members at a node: the largest contact radius
// (core/contact/ContactSearch.h sectionRadius) of the elements holding it; 0 when none
// gives a section.
double halfSectionDepth(const Model& model, int node);

// The debris CSV: one header, one row per run (same columns in the plans table).
std::string debrisCsvHeader();  // "left,right,height,total_mass,outside_mass,site,..."
std::string debrisCsvRow(const DebrisFigures& d);
// The columns of each protected zone after those (the zones' names, in order):
// mass_<z>,hit_<z> (1 or 0),heaviest_<z>,flyrock_count_<z>,flyrock_mass_<z>,
// x1_<z>,x2_<z> (where the zone lies; empty on a side's unbounded end).
extern const std::vector<std::string> kZoneColumns;  // "mass_", "hit_", ...
std::string zoneCsvHeader(const std::vector<std::string>& zones);
// The zones' cells of d for the names given (empty cells for a zone d lacks).
std::string zoneCsvCells(const DebrisFigures& d, const std::vector<std::string>& zones);
// The names of the zones of d, in order.
std::vector<std::string> zoneNames(const DebrisFigures& d);
// The names of the site's zones (protectedZones), none without a site.
std::vector<std::string> zoneNames(const std::optional<Site>& site);
// The debris header with the zones' columns after it.
std::string debrisCsvHeader(const std::vector<std::string>& zones);
// The row of d with the zones' cells after it.
std::string debrisCsvRow(const DebrisFigures& d, const std::vector<std::string>& zones);
// The log's debris lines (units m, t, kN, s), each starting with "  debris: ".
std::string debrisLogLines(const DebrisFigures& d);

}  // namespace c2d
