#include "macro/mesh/SiteCommand.h"

#include <algorithm>
#include <cctype>
#include <ostream>

namespace c2d {

using namespace meshspec;

namespace {

const std::string kSyntax = "SITE,,xmin,xmax[,dir]";
const std::string kZoneSyntax = "name x1 x2 [h [mass]], FLYRock,,mass or RISK,,p[,confidence]";

FallDirection readDirection(const Record& h) {
  if (h.size() < 5 || h[4].text.empty()) return FallDirection::None;
  const std::string& w = h[4].text;
  if (keywordMatches(w, "LEFT")) return FallDirection::Left;
  if (keywordMatches(w, "RIGHt")) return FallDirection::Right;
  if (keywordMatches(w, "DOWN")) return FallDirection::Down;
  failAt(h, 4, "unknown direction '" + w + "'",
         "write LEFT or RIGHt (felled toward that side) or DOWN (imploded)");
}

// A zone's name names columns (p_<name>, mass_<name>): a letter, then letters,
// digits or '_'.
bool validZoneName(const std::string& s) {
  if (s.empty() || !std::isalpha(static_cast<unsigned char>(s[0]))) return false;
  return std::all_of(s.begin(), s.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

ProtectedZone readZone(MeshContext& ctx, const Record& r, const Site& site) {
  ctx.maxFields(r, 5, kZoneSyntax);
  ProtectedZone z;
  z.name = r[0].text;
  if (!validZoneName(z.name))
    failAt(r, 0, "'" + z.name + "' is not a zone name",
           "a zone's name starts with a letter, then letters, digits or '_': " + kZoneSyntax);
  const std::string key = lower(z.name);
  if (key == "left" || key == "right")
    failAt(r, 0, "'" + z.name + "' is the name of a side of the site",
           "the sides outside [xmin, xmax] are zones of their own; name the object otherwise");
  for (const ProtectedZone& o : site.objects)
    if (lower(o.name) == key) failAt(r, 0, "a second zone named '" + z.name + "'");
  if (r.size() < 3 || r[2].text.empty())
    failAt(r, std::min<std::size_t>(r.size(), 2), "the zone needs x1 and x2", kZoneSyntax);
  z.x1 = ctx.number(r, 1);
  z.x2 = ctx.number(r, 2);
  if (!(z.x2 > z.x1)) failAt(r, 2, "x2 must be greater than x1");
  if (r.size() > 3) z.height = ctx.number(r, 3);
  if (r.size() > 4) z.mass = ctx.number(r, 4);
  if (z.height < 0) failAt(r, 3, "the height must not be negative (0: debris at any height)");
  if (z.mass < 0) failAt(r, 4, "the mass must not be negative (0: none may land there)");
  return z;
}

void readRecords(MeshContext& ctx, const MeshCommand& cmd, Site& s) {
  bool flyrock = false, risk = false;
  for (const Record& r : cmd.data) {
    if (r.is("FLYRock")) {
      ctx.maxFields(r, 3, "FLYRock,,mass");
      if (flyrock) failAt(r, 0, "a second FLYRock record");
      if (!r.text(1).empty()) failAt(r, 1, "FLYRock takes no option word", "write FLYRock,,mass");
      s.flyrockMass = ctx.number(r, 2);
      if (!(s.flyrockMass >= 0)) failAt(r, 2, "the flyrock mass must not be negative");
      flyrock = true;
    } else if (r.is("RISK")) {
      ctx.maxFields(r, 4, "RISK,,p[,confidence]");
      if (risk) failAt(r, 0, "a second RISK record");
      if (!r.text(1).empty()) failAt(r, 1, "RISK takes no option word", "write RISK,,p,confidence");
      s.riskLevel = ctx.number(r, 2);
      if (!(s.riskLevel > 0 && s.riskLevel < 1)) failAt(r, 2, "the risk p must lie in (0, 1)");
      if (r.size() > 3 && !r[3].text.empty()) s.riskConfidence = ctx.number(r, 3);
      if (!(s.riskConfidence > 0 && s.riskConfidence < 1))
        failAt(r, 3, "the confidence must lie in (0, 1)", "e.g. 0.95");
      risk = true;
    } else {
      s.objects.push_back(readZone(ctx, r, s));
    }
  }
}

void echoSite(std::ostream& os, const Site& s) {
  title(os, "S i t e");
  os << "      xmin ";
  num(os, s.xmin) << "   xmax ";
  num(os, s.xmax) << "\n";
  if (s.dir != FallDirection::None) os << "      intended fall " << fallDirectionName(s.dir) << "\n";
  for (const ProtectedZone& z : s.objects) {
    os << "      zone " << z.name << "   x1 ";
    num(os, z.x1) << "   x2 ";
    num(os, z.x2) << "   h ";
    num(os, z.height) << "   mass ";
    num(os, z.mass) << "\n";
  }
  if (s.flyrockMass >= 0) {
    os << "      flyrock below ";
    num(os, s.flyrockMass) << "\n";
  }
}

void applySite(MeshContext& ctx, const MeshCommand& cmd) {
  const Record& h = cmd.head;
  ctx.maxFields(h, 5, kSyntax);
  if (!h.text(1).empty())
    failAt(h, 1, "SITE takes no option word (its second field is empty)", "write " + kSyntax);
  if (h.size() < 4 || h[3].text.empty())
    failAt(h, h.size() < 4 ? h.size() : 3, "SITE needs xmin and xmax", "write " + kSyntax);
  Site s;
  s.xmin = ctx.number(h, 2);
  s.xmax = ctx.number(h, 3);
  if (!(s.xmax > s.xmin)) failAt(h, 3, "xmax must be greater than xmin");
  s.dir = readDirection(h);
  // One site per mesh input (a MESH re-entry may give a new one).
  if (!ctx.siteOrigin.blank())
    failAt(h, 0,
           "a second SITE (the first is on line " + std::to_string(ctx.siteOrigin.loc.line) + ")",
           "give one SITE");
  readRecords(ctx, cmd, s);
  ctx.siteOrigin = h;
  ctx.model.site() = s;
  if (auto* os = ctx.out()) echoSite(*os, s);
}

}  // namespace

MeshCommandEntry siteCommandEntry() {
  CommandSpec spec = meshSpec(
      "SITE",
      "The site: the debris must stay in xmin <= x <= xmax (the debris CSV, PLOT,DEBRis and "
      "the summary say whether it did). dir: LEFT or RIGHt, the building is felled toward that "
      "side, which receives the debris; DOWN, it is imploded. Every run with dir gets a verdict "
      "from the move of its mass centroid s (+ toward dir) against T = max((H - W)/4, H/20), H "
      "the building's height above the ground, W its footprint's width ((H - W)/2 is the move of "
      "a rigid body tipped about its back edge; half of that counts): felled when s >= T, other "
      "way when s <= -T, in place between; for DOWN in place (|s| < T) is the intended outcome "
      "and a larger move either way is felled. The log gives beside it the largest tilt of the "
      "members vertical at the start that still stand (tilted less than 60 degrees). The sides "
      "outside [xmin, xmax] are the zones left and right, unless dir names that side. Optional "
      "records up to a blank record: a protected zone 'name x1 x2 [h [mass]]' (debris lying in "
      "x1 <= x <= x2 at or above h over the ground, h = 0: at any height, hits it when its mass "
      "exceeds mass t, default 0); FLYRock,,mass: pieces lighter than mass t are flying "
      "fragments, counted apart from the debris bed, whose figures (reaches, centroid, mass "
      "outside) leave them out (default 1 % of the building's mass); RISK,,p,confidence: the "
      "probability each zone's hit must be shown below, with the confidence (default 0.01 and "
      "0.95, the exact binomial (Clopper-Pearson) bound). Records follow only when the next "
      "record is not a command; a zone's name must not start with a mesh command's four "
      "letters. One SITE per mesh input.",
      {text("", "empty"), expr("xmin", "left limit"), expr("xmax", "right limit"),
       text("dir", "LEFT, RIGHt or DOWN: the intended fall", "none")},
      kZoneSyntax,
      {text("name", "the zone's name (a letter, then letters, digits, '_')"),
       expr("x1", "left end"), expr("x2", "right end"),
       expr("h", "height over the ground debris must not reach there (0: any)", "0"),
       expr("mass", "mass that may land there", "0")});
  spec.data = DataForm::Optional;
  return {spec, applySite};
}

}  // namespace c2d
