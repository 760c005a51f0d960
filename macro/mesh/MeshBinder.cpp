#include "macro/mesh/MeshBinder.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <iomanip>
#include <limits>
#include <map>
#include <ostream>
#include <set>
#include <sstream>

#include "macro/deck/DeckParser.h"
#include "macro/deck/Expression.h"
#include "macro/deck/Limits.h"

namespace c2d {

MeshBinder::MeshBinder(Model& model, Parameters& params, std::ostream* echo, Warnings* warnings)
    : ctx_(model, params, echo), table_(meshCommandTable()), registry_("Mesh commands") {
  for (const auto& e : table_) registry_.add(e.spec);
  ctx_.warnings = warnings;
}

namespace {
const char* const kControlNames[] = {"numnp", "numel", "nummat", "ndm", "ndf",
                                     "nen",   "nad",   "npd",    "nud"};
}  // namespace

ControlData MeshBinder::setControl(const Record& r) {
  ctx_.maxFields(r, 9, "numnp numel nummat ndm ndf nen [nad npd nud]");
  std::array<int, 9> v{};
  std::array<ControlField, 9> at{};
  for (std::size_t i = 0; i < 9; ++i) {
    v[i] = ctx_.integer(r, i, kControlNames[i]);
    at[i] = {&r, i};
  }
  return applyControl(v, at,
                      "the control record is: numnp numel nummat ndm ndf nen (zeros: counted), "
                      "e.g. 0 0 0 2 3 2");
}

ControlData MeshBinder::setControl(const std::vector<Record>& keywords) {
  // Not given: counted (nodes, elements, materials), what frames are (2, 3, 2), 0.
  std::array<int, 9> v{0, 0, 0, 2, 3, 2, 0, 0, 0};
  std::array<ControlField, 9> at{};
  at.fill({&keywords.front(), 0});
  std::array<bool, 9> given{};
  for (const Record& r : keywords)
    for (std::size_t i = 0; i + 1 < r.size(); i += 2) {
      const int k = controlKeywordIndex(r[i].text);
      if (given[k])
        throw DeckError(r[i].loc, "control keyword '" + r[i].text + "' is given twice",
                        r.excerpt(r[i].loc));
      given[k] = true;
      v[k] = ctx_.integer(r, i + 1, kControlNames[k]);
      at[k] = {&r, i + 1};
    }
  return applyControl(v, at,
                      "the keyword form of the control record: NODEs=n ELEMents=n MATErial=n "
                      "(0 or absent: counted) DIMEnsion=2 DOFS=3 ELNOdes=2");
}

ControlData MeshBinder::applyControl(const std::array<int, 9>& v,
                                     const std::array<ControlField, 9>& at,
                                     const std::string& hint) {
  const auto& names = kControlNames;
  ControlData c;
  auto fail = [&](std::size_t i, const std::string& msg) {
    const Record& r = *at[i].record;
    throw DeckError(r.fieldLoc(at[i].field), msg, r.excerpt(r.fieldLoc(at[i].field)), hint);
  };
  for (std::size_t i = 0; i < 3; ++i)
    if (v[i] < 0) fail(i, std::string(names[i]) + " must not be negative");
  const long long limit[3] = {DeckLimits::maxNodes(), DeckLimits::maxElements(),
                              DeckLimits::kMaxMaterials};
  for (std::size_t i = 0; i < 3; ++i)
    if (v[i] > 0) checkNumber(*at[i].record, at[i].field, v[i], limit[i], names[i]);
  if (v[3] != 2) fail(3, "ndm must be 2 (plane frames), got " + std::to_string(v[3]));
  if (v[4] != 3) fail(4, "ndf must be 3 (u, v, theta), got " + std::to_string(v[4]));
  if (v[5] != 0 && v[5] != 2)
    fail(5, "nen must be 2 (two-node elements) or 0, got " + std::to_string(v[5]));
  for (std::size_t i = 6; i < 9; ++i)
    if (v[i] != 0) fail(i, std::string(names[i]) + " is not used by frames: leave it 0");
  c.numnp = v[0];
  c.numel = v[1];
  c.nummat = v[2];
  c.nen = 2;
  ctx_.maxNodes = c.numnp;
  ctx_.maxElements = c.numel;
  ctx_.maxMaterials = c.nummat;
  if (c.numnp > 0) ctx_.model.resizeNodes(c.numnp);
  if (ctx_.echo) {
    auto& os = *ctx_.echo;
    auto count = [](int n) { return n > 0 ? std::to_string(n) : std::string("counted"); };
    os << "\n   Number of nodal points      = " << count(c.numnp)
       << "\n   Number of elements          = " << count(c.numel)
       << "\n   Number of material sets     = " << count(c.nummat)
       << "\n   Dimension of coordinates    = " << c.ndm
       << "\n   Degrees of freedom per node = " << c.ndf
       << "\n   Nodes per element           = " << c.nen << "\n";
  }
  return c;
}

void MeshBinder::apply(const std::vector<MeshItem>& items) {
  for (const auto& item : items) {
    if (const auto* block = std::get_if<ParamBlock>(&item)) {
      for (const auto& a : block->assigns) {
        const double value = a.value.eval(ctx_.params);
        ctx_.params.assign(a.name, value, a.record[0]);
        if (auto* os = ctx_.out())
          *os << "      Parameter " << a.name << " = " << std::setprecision(10) << value << "\n";
      }
      continue;
    }
    const auto& cmd = std::get<MeshCommand>(item);
    const MeshCommandEntry* entry = nullptr;
    for (const auto& e : table_)
      if (e.spec.matches(cmd.head[0].text)) entry = &e;
    if (!entry || !entry->apply) {
      const std::string hint = registry_.suggest(cmd.head[0].text);
      throw DeckError(cmd.head[0].loc, "'" + cmd.head[0].text + "' is not a mesh command here",
                      cmd.head.excerpt(cmd.head[0].loc), hint);
    }
    entry->apply(ctx_, cmd);
  }
}

void MeshBinder::finish(const SourceLoc& where, const std::string& whereText) {
  finishMesh(ctx_, where, whereText);
}

namespace {

// "3, 4, 7" (at most ten, then "and n more").
std::string nodeList(const std::vector<int>& nodes) {
  std::string s;
  for (std::size_t i = 0; i < nodes.size() && i < 10; ++i)
    s += (i ? ", " : "") + std::to_string(nodes[i]);
  if (nodes.size() > 10) s += " and " + std::to_string(nodes.size() - 10) + " more";
  return s;
}

// Nodes below the ground line y0 at their coordinates plus u (null: none),
// by more than 1e-3 of the mesh size (a node resting on the ground at its
// penalty penetration W/k, far below that, starts at rest): they would be
// thrown out of the ground by the penalty force. With u, only the nodes that
// elements hold (a node a removal left is out of the model). The message
// names them and the deepest; empty when there are none.
std::string nodesInsideGround(const Model& model, double y0, const Eigen::VectorXd* u,
                              const std::string& when) {
  const double tol = 1e-3 * model.characteristicLength();
  std::vector<char> held(static_cast<std::size_t>(model.numNodes()), u ? 0 : 1);
  if (u)
    for (const auto& el : model.elements())
      if (el)
        for (int n : el->nodes()) held[static_cast<std::size_t>(n)] = 1;
  auto y = [&](int n) {
    const Eigen::Index i = static_cast<Eigen::Index>(n) * kNodeDofs + 1;
    return model.coord(n).y() + (u && i < u->size() ? (*u)[i] : 0.0);
  };
  std::vector<int> below;
  int deepest = -1;
  for (int n = 0; n < model.numNodes(); ++n) {
    if (!held[static_cast<std::size_t>(n)] || !model.hasCoord(n) || y(n) >= y0 - tol) continue;
    below.push_back(n + 1);
    if (deepest < 0 || y(n) < y(deepest)) deepest = n;
  }
  if (below.empty()) return {};
  std::ostringstream msg;
  msg << (below.size() == 1 ? "node " : "nodes ") << nodeList(below)
      << (below.size() == 1 ? " lies" : " lie") << " inside the ground y0 = " << y0 << " " << when
      << " (the deepest, node " << deepest + 1 << ", " << y0 - y(deepest) << " below it)";
  return msg.str();
}

// A warning at field i of r, when the context gathers warnings.
void warnAt(const MeshContext& ctx, const Record& r, std::size_t i, const std::string& msg) {
  if (ctx.warnings) ctx.warnings->add(r.fieldLoc(i), msg, r.excerpt(r.fieldLoc(i)));
}

// No node inside the ground at the start.
void checkGroundClear(const MeshContext& ctx) {
  const Model& model = ctx.model;
  if (const auto& g = model.ground(); g && !ctx.groundOrigin.blank()) {
    const std::string inside = nodesInsideGround(model, g->y0, nullptr, "at the start");
    if (!inside.empty()) {
      const Record& r = ctx.groundOrigin;
      throw DeckError(r.fieldLoc(2), inside, r.excerpt(r.fieldLoc(2)),
                      "put the ground at or below the lowest node");
    }
  }
}

// A contact penalty no step resolves: beyond 1/eps times the members' largest
// axial stiffness EA/L, their stiffness drowns in the round-off of the
// contact's in every tangent, static or dynamic (k + m/(beta dt^2) + EA/L:
// a step short enough for the contact's period 2 pi sqrt(m/k), which is
// then sqrt(eps) of the members', makes the inertia term drown it too). The
// penetrations are of round-off size and the contact's forces and energies
// overflow.
void warnUnresolvedPenalties(const MeshContext& ctx) {
  const Model& model = ctx.model;
  double stiffest = 0;
  for (const auto& el : model.elements())
    if (el)
      if (const MaterialSet* m = model.material(el->materialNumber())) {
        const auto n = el->nodes();
        const double l = (model.coord(n[1]) - model.coord(n[0])).norm();
        if (l > 0) stiffest = std::max(stiffest, m->EA() / l);
      }
  auto checkPenalty = [&](const Record& r, std::size_t field, double k) {
    const double limit = stiffest / std::numeric_limits<double>::epsilon();
    if (r.blank() || !(stiffest > 0) || k <= limit) return;
    std::ostringstream msg;
    msg << "the penalty k = " << k << " is " << k / stiffest
        << " times the members' largest axial stiffness EA/L = " << stiffest
        << ", more than double precision resolves (" << 1 / std::numeric_limits<double>::epsilon()
        << "): no step resolves the contact and the members together";
    warnAt(ctx, r, field, msg.str());
  };
  if (const auto& g = model.ground()) checkPenalty(ctx.groundOrigin, 3, g->k);
  if (const auto& c = model.memberContact()) checkPenalty(ctx.membersOrigin, 2, c->k);
}

// GRAVity needs some mass (DENSity, QLOAd carried as mass, MASS); the material
// sets without DENSity get a warning.
void checkGravityMass(const MeshContext& ctx) {
  const Model& model = ctx.model;
  std::set<int> without;
  bool someMass = false;
  for (const auto& el : model.elements()) {
    if (!el) continue;
    const MaterialSet* m = model.material(el->materialNumber());
    if (!m) continue;
    if (m->density > 0)
      someMass = true;
    else
      without.insert(m->number);
  }
  for (const ElementLoad& q : model.elementLoads()) someMass = someMass || q.asMass;
  for (int n = 0; n < model.numNodes() && !someMass; ++n)
    for (double m : model.nodalMass(n)) someMass = someMass || m > 0;
  const Record& r = ctx.gravityOrigin;
  if (!someMass)
    throw DeckError(r.fieldLoc(0), "GRAVity, but no material set has a density: no self-weight",
                    r.excerpt(r.fieldLoc(0)), "give DENSity,,rho in the material sets");
  if (!without.empty()) {
    std::string sets;
    for (int m : without) sets += (sets.empty() ? "" : ", ") + std::to_string(m);
    warnAt(ctx, r, 0,
           std::string(without.size() == 1 ? "material set " : "material sets ") + sets +
               " without DENSity: GRAVity gives their elements no self-weight");
  }
}

// Nodes with coordinates that no element uses: one warning per record that gave them.
void warnUnusedNodes(const MeshContext& ctx) {
  const Model& model = ctx.model;
  std::vector<char> used(static_cast<std::size_t>(model.numNodes()), 0);
  for (const auto& el : model.elements())
    if (el)
      for (int n : el->nodes()) used[static_cast<std::size_t>(n)] = 1;
  std::map<const Record*, std::vector<int>> unused;
  for (int n = 0; n < model.numNodes(); ++n)
    if (model.hasCoord(n) && !used[static_cast<std::size_t>(n)] &&
        n < static_cast<int>(ctx.coordOrigin.size()) && ctx.coordOrigin[n])
      unused[ctx.coordOrigin[n]].push_back(n + 1);
  for (const auto& [rec, nodes] : unused)
    warnAt(ctx, *rec, 0,
           std::string(nodes.size() == 1 ? "node " : "nodes ") + nodeList(nodes) +
               (nodes.size() == 1 ? " is" : " are") + " used by no element");
}

}  // namespace

void MeshBinder::checkInitialMesh() {
  checkGroundClear(ctx_);
  warnUnresolvedPenalties(ctx_);
  if (ctx_.model.gravity() != Vec2::Zero() && !ctx_.gravityOrigin.blank()) checkGravityMass(ctx_);
  if (ctx_.meshChecks) ctx_.meshChecks(ctx_);
  warnUnusedNodes(ctx_);
}

Model buildModel(const Problem& problem, Parameters& params, std::ostream* echo, MeshFacts* facts) {
  Model model;
  if (echo) *echo << "\n   " << problem.title << "\n";
  MeshBinder binder(model, params, echo, facts ? facts->warnings : nullptr);
  if (facts) binder.setBeforeElements(facts->beforeElements);
  if (problem.controlKeywords.empty())
    binder.setControl(problem.control);
  else
    binder.setControl(problem.controlKeywords);
  binder.apply(problem.mesh);
  binder.finish(problem.meshEnd.loc, problem.meshEnd.lineText());
  if (model.numElements() == 0)
    throw DeckError(problem.meshEnd.loc, "the mesh has no elements", problem.meshEnd.lineText(),
                    "give ELEMents (or a BLOCk) before END");
  binder.checkInitialMesh();
  if (facts) facts->loadTables = binder.loadTableRefs();
  return model;
}

void MeshBinder::checkGroundReentry(const std::optional<Ground>& before, const State* state) {
  const Model& model = ctx_.model;
  const auto& g = model.ground();
  if (!g || ctx_.groundOrigin.blank()) return;
  // The same ground or a lower one keeps the nodes that rest in it where they are.
  const double tol = 1e-3 * model.characteristicLength();
  if (before && g->y0 <= before->y0 + tol) return;
  char when[64];
  std::snprintf(when, sizeof when, "at the MESH re-entry (t = %.6e)", state ? state->t : 0.0);
  const std::string inside = nodesInsideGround(model, g->y0, state ? &state->u : nullptr, when);
  if (inside.empty()) return;
  const Record& r = ctx_.groundOrigin;
  throw AnalysisError(r.fieldLoc(2).str() + ": error: " + inside +
                      "\n    put the ground at or below the lowest node");
}

void applyMesh(const std::vector<MeshItem>& items, Parameters& params, Model& model,
               std::ostream* echo, const Record* end, const State* state) {
  const std::optional<Ground> ground = model.ground();
  MeshBinder binder(model, params, echo);
  binder.setState(state);
  binder.apply(items);
  SourceLoc where;
  std::string text;
  if (end) {
    where = end->loc;
    text = end->lineText();
  } else if (!items.empty()) {
    const Record& last =
        std::visit([](const auto& i) -> const Record& { return i.head; }, items.back());
    where = last.loc;
    text = last.lineText();
  }
  binder.finish(where, text);
  binder.checkGroundReentry(ground, state);
}

}  // namespace c2d
