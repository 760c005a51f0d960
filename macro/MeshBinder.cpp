#include "macro/MeshBinder.h"

#include <iomanip>
#include <ostream>

#include "macro/Expression.h"

namespace c2d {

MeshBinder::MeshBinder(Model& model, Parameters& params, std::ostream* echo)
    : ctx_(model, params, echo), table_(meshCommandTable()), registry_("Mesh commands") {
  for (const auto& e : table_) registry_.add(e.spec);
}

ControlData MeshBinder::setControl(const Record& r) {
  ctx_.maxFields(r, 9, "numnp numel nummat ndm ndf nen [nad npd nud]");
  ControlData c;
  const char* names[] = {"numnp", "numel", "nummat", "ndm", "ndf", "nen", "nad", "npd", "nud"};
  int v[9] = {};
  for (std::size_t i = 0; i < 9; ++i) v[i] = ctx_.integer(r, i, names[i]);
  auto fail = [&](std::size_t i, const std::string& msg) {
    throw DeckError(r.fieldLoc(i), msg, r.excerpt(r.fieldLoc(i)),
                    "the control record is: numnp numel nummat ndm ndf nen (zeros: counted), "
                    "e.g. 0 0 0 2 3 2");
  };
  for (std::size_t i = 0; i < 3; ++i)
    if (v[i] < 0) fail(i, std::string(names[i]) + " must not be negative");
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
        ctx_.params.set(a.name, value);
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

Model buildModel(const Problem& problem, Parameters& params, std::ostream* echo) {
  Model model;
  if (echo) *echo << "\n   " << problem.title << "\n";
  MeshBinder binder(model, params, echo);
  binder.setControl(problem.control);
  binder.apply(problem.mesh);
  binder.finish(problem.meshEnd.loc, problem.meshEnd.lineText());
  if (model.numElements() == 0)
    throw DeckError(problem.meshEnd.loc, "the mesh has no elements", problem.meshEnd.lineText(),
                    "give ELEMents (or a BLOCk) before END");
  return model;
}

void applyMesh(const std::vector<MeshItem>& items, Parameters& params, Model& model,
               std::ostream* echo, const Record* end, const State* state) {
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
}

}  // namespace c2d
