// The mesh command CONTact: the ground (GROUnd) and contact between members
// (MEMBers), with their penalty, damping ratio, friction and restitution.
#include "macro/mesh/MeshCommands.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <set>
#include <sstream>

#include "macro/deck/Limits.h"

namespace c2d {

using namespace meshspec;

namespace {

// An optional non-negative number at field i (absent or empty: dflt).
double optionalNumber(MeshContext& ctx, const Record& r, std::size_t i, double dflt,
                      const char* what, const char* hint) {
  if (r.size() <= i || r[i].text.empty()) return dflt;
  const double v = ctx.number(r, i);
  if (v < 0) failAt(r, i, std::string(what) + " must not be negative", hint);
  return v;
}

// The restitution e at field i: in (0, 1], absent or empty 1.
double restitutionAt(MeshContext& ctx, const Record& r, std::size_t i) {
  const double e = r.size() > i && !r[i].text.empty() ? ctx.number(r, i) : 1.0;
  if (!(e > 0 && e <= 1))
    failAt(r, i, "the restitution e must lie in (0, 1]", "1 or absent: an elastic impact");
  return e;
}

void echoMemberContact(std::ostream& os, const MemberContactData& c) {
  title(os, "M e m b e r   C o n t a c t");
  os << "      k ";
  num(os, c.k);
  if (c.zeta > 0) num(os << "   zeta ", c.zeta);
  os << "   r ";
  if (c.radius < 0)
    os << "(sections; 1e-3 of the shortest element without)";
  else
    num(os, c.radius);
  if (c.mu > 0) num(os << "   mu ", c.mu);
  if (c.restitution < 1) num(os << "   e ", c.restitution);
  os << "\n";
}

// MEMBers,,k[,zeta[,r[,mu[,e]]]]: contact between members; k = 0 switches it off.
void readMemberContact(MeshContext& ctx, const Record& r) {
  ctx.maxFields(r, 7, "MEMBers,,k[,zeta[,r[,mu[,e]]]]");
  if (!r.text(1).empty())
    failAt(r, 1, "MEMBers takes no option word (its second field is empty)",
           "write MEMBers,,k[,zeta[,r[,mu[,e]]]]");
  MemberContactData c;
  c.k = ctx.number(r, 2);
  if (c.k < 0) failAt(r, 2, "penalty stiffness k must not be negative", "0: no member contact");
  c.zeta = optionalNumber(ctx, r, 3, 0.0, "the damping ratio zeta", "0 or absent: no dashpot");
  c.radius = optionalNumber(ctx, r, 4, -1.0, "the contact radius r", "leave it out for the default");
  c.mu = optionalNumber(ctx, r, 5, 0.0, "the friction coefficient mu", "0 or absent: frictionless");
  c.restitution = restitutionAt(ctx, r, 6);
  ctx.membersOrigin = r;
  ctx.topologyChanged = true;  // contact pairs enter or leave the sparsity pattern
  if (c.k == 0) {  // a study's switch: no member contact
    ctx.model.memberContact().reset();
    if (auto* os = ctx.out()) {
      title(*os, "M e m b e r   C o n t a c t");
      *os << "      off (k = 0"
          << (r.size() > 3 ? ": the record's other values are not used" : "") << ")\n";
    }
    return;
  }
  ctx.model.memberContact() = c;
  if (auto* os = ctx.out()) echoMemberContact(*os, c);
}

// GROUnd,,y0,k[,zeta[,mu[,e]]]: one ground per mesh input, in one CONTact
// command or several (a MESH re-entry may give a new one).
void readGround(MeshContext& ctx, const Record& r) {
  if (!ctx.groundOrigin.blank())
    failAt(r, 0,
           "a second GROUnd record (the first is on line " +
               std::to_string(ctx.groundOrigin.loc.line) + ")");
  ctx.maxFields(r, 7, "GROUnd,,y0,k[,zeta[,mu[,e]]]");
  if (!r.text(1).empty())
    failAt(r, 1, "GROUnd takes no option word (its second field is empty)",
           "write GROUnd,,y0,k[,zeta[,mu[,e]]]");
  Ground g;
  g.y0 = ctx.number(r, 2);
  g.k = ctx.number(r, 3);
  if (g.k <= 0) failAt(r, 3, "penalty stiffness k must be positive");
  g.zeta = optionalNumber(ctx, r, 4, 0.0, "the damping ratio zeta", "0 or absent: no dashpot");
  g.mu = optionalNumber(ctx, r, 5, 0.0, "the friction coefficient mu", "0 or absent: frictionless");
  g.restitution = restitutionAt(ctx, r, 6);
  ctx.model.ground() = g;
  ctx.groundOrigin = r;
  if (auto* os = ctx.out()) {
    title(*os, "G r o u n d   C o n t a c t");
    *os << "      y0 ";
    num(*os, g.y0) << "   k ";
    num(*os, g.k);
    if (g.zeta > 0) num(*os << "   zeta ", g.zeta);
    if (g.mu > 0) num(*os << "   mu ", g.mu);
    if (g.restitution < 1) num(*os << "   e ", g.restitution);
    *os << "\n";
  }
}

void applyContact(MeshContext& ctx, const MeshCommand& cmd) {
  const Record* ground = nullptr;
  const Record* members = nullptr;
  for (const Record& r : cmd.data) {
    if (r.is("MEMBers")) {
      if (members)
        failAt(r, 0,
               "a second MEMBers record (the first is on line " +
                   std::to_string(members->loc.line) + ")");
      readMemberContact(ctx, r);
      members = &r;
    } else if (r.is("GROUnd")) {
      readGround(ctx, r);
      ground = &r;
    } else {
      std::string hint =
          "the records are 'GROUnd,,y0,k[,zeta[,mu[,e]]]' and 'MEMBers,,k[,zeta[,r[,mu[,e]]]]'";
      failAt(r, 0, "unknown contact type '" + r.text(0) + "'", hint);
    }
  }
  if (!ground && !members)
    failAt(cmd.head, 0, "CONTact has no GROUnd or MEMBers record", "write GROUnd,,y0,k");
}

}  // namespace

std::vector<MeshCommandEntry> contactCommandTable() {
  std::vector<MeshCommandEntry> t;
  t.push_back(
      {meshSpec(
           "CONTact",
           "Penalty contact. GROUnd: rigid ground y = y0 for every node, penalty stiffness "
           "k (kN/m per node); zeta: damping ratio of a dashpot c dp/dt on the "
           "penetration p while the node touches, c = 2 zeta sqrt(k m) for the node's "
           "own mass m (1: critical; absent or 0: none), the same at every step (this "
           "field was alpha, a damper alpha k dt that vanished with the step: a value "
           "there is now read as zeta); mu: "
           "Coulomb friction: each node held by a horizontal stick element anchored where "
           "it last slid, a spring of stiffness k beside a critical dashpot 2 sqrt(k m) "
           "(m the node's mass), sliding when the element's force reaches mu N (N the "
           "contact's normal force, its dashpot's part included; the spring holds a load "
           "at rest without creep and stores at most (mu N)^2/(2k); the dashpot meets a "
           "sudden slip at once, so that an impact takes Coulomb's impulse mu int N dt "
           "whatever DT); e: restitution of an impact "
           "(below 1 the contact crushes: loading with k beyond the largest penetration q "
           "since the node touched down, unloading and reloading with k/e^2 below it, so "
           "that a node strikes with speed v and leaves with e v; the work k(p^2 - "
           "q^2)(1 - e^2)/2 is dissipated, whatever DT: a dynamic step through an impact is "
           "taken in shorter parts where a contact needs it). The run reports the deepest any node "
           "went "
           "into the ground and warns when it is deeper than half its members' section "
           "depth sqrt(3 I/A) (k too soft for the impact). "
           "MEMBers,,k[,zeta[,r[,mu[,e]]]]: "
           "contact of every node with every element it is not part of "
           "(nor tied to by a joint), at the distance r_node + r_element with "
           "r = sqrt(3 I/A), half the section depth (r: the radius of members whose "
           "material has no A and I, default 1e-3 of the shortest element); mu and e: "
           "the ground's friction (along the member, its stick dashpot for the pair's "
           "reduced mass) and crushing law, per pair, and "
           "zeta its dashpot for the pair's reduced mass; k = 0: "
           "no member contact (a study's switch). Pairs already that close in the "
           "reference configuration do not contact while the members between them hold; "
           "a joint that ruptures sets them free, and pieces inside each other's contact "
           "distance then start at zero force, their full distance returning as they "
           "separate. One GROUnd per mesh input (a MESH re-entry may give another, not "
           "above the nodes); a k beyond 1/eps = 4.5e15 times the members' largest "
           "EA/L is warned: no step resolves the contact and the members together.",
           {}, "GROUnd,,y0,k[,zeta[,mu[,e]]] and/or MEMBers,,k[,zeta[,r[,mu[,e]]]]",
           {text("GROUnd", "contact type (or MEMBers)"), text("", "empty"),
            expr("y0", "ground level (MEMBers: k)"),
            expr("k", "penalty stiffness, kN/m per node (MEMBers: zeta)"),
            expr("zeta", "damping ratio of the contact's dashpot (MEMBers: r)", "0"),
            expr("mu", "friction coefficient", "0"), expr("e", "restitution of an impact", "1")}),
       applyContact});
  return t;
}

}  // namespace c2d
