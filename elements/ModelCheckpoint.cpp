#include "elements/ModelCheckpoint.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include "core/io/Checkpoint.h"
#include "elements/InelasticFrame.h"
#include "elements/InfillStrut.h"
#include "elements/JointedElement.h"
#include "elements/LinearFrame.h"
#include "elements/ReissnerFrame.h"
#include "materials/SectionLaws.h"

namespace c2d {

namespace {

using namespace checkpoint;

// Strut: an infill strut, whose construction data are its state (no material set).
enum class ElementKind : std::uint8_t { Linear = 1, Reissner = 2, Inelastic = 3, Jointed = 4, Strut = 5 };

ElementKind kindOf(const Element& e) {
  if (dynamic_cast<const JointedElement*>(&e)) return ElementKind::Jointed;
  if (dynamic_cast<const InfillStrut*>(&e)) return ElementKind::Strut;
  if (dynamic_cast<const InelasticFrame*>(&e)) return ElementKind::Inelastic;
  if (dynamic_cast<const ReissnerFrame*>(&e)) return ElementKind::Reissner;
  if (dynamic_cast<const LinearFrame*>(&e)) return ElementKind::Linear;
  throw CheckpointError("element type '" + e.typeName() + "' cannot be written to a restart file");
}

std::unique_ptr<Element> build(ElementKind kind, const Model& model, int material,
                               const std::array<int, 2>& nodes) {
  const MaterialSet* mat = model.material(material);
  if (!mat)
    throw CheckpointError("element of material set " + std::to_string(material) +
                          ", which is not in the file");
  for (int n : nodes)
    if (n < 0 || n >= model.numNodes())
      throw CheckpointError("element node " + std::to_string(n + 1) + " out of range");
  const Vec2& x1 = model.coord(nodes[0]);
  const Vec2& x2 = model.coord(nodes[1]);
  try {
    switch (kind) {
      case ElementKind::Linear:
        return std::make_unique<LinearFrame>(*mat, nodes, x1, x2);
      case ElementKind::Reissner:
        return std::make_unique<ReissnerFrame>(*mat, nodes, x1, x2);
      case ElementKind::Inelastic:
        return std::make_unique<InelasticFrame>(*mat, nodes, x1, x2);
      case ElementKind::Jointed:
      case ElementKind::Strut:
        break;
    }
  } catch (const std::invalid_argument& e) {
    throw CheckpointError(std::string("element cannot be rebuilt: ") + e.what());
  }
  throw CheckpointError("bad element kind");
}

}  // namespace

void writeElement(std::ostream& out, const Element& element) {
  const ElementKind kind = kindOf(element);
  put(out, kind);
  put(out, element.materialNumber());
  for (int n : element.nodes()) put(out, n);
  if (kind == ElementKind::Jointed) {
    const auto& j = static_cast<const JointedElement&>(element);
    put(out, j.slaveEnd());
    put(out, j.masterNode());
    writeElement(out, j.inner());
  }
  const auto* c = dynamic_cast<const Checkpoint*>(&element);
  if (!c)
    throw CheckpointError("element type '" + element.typeName() +
                          "' cannot be written to a restart file");
  c->writeState(out);
}

std::unique_ptr<Element> readElement(std::istream& in, const Model& model) {
  const auto kind = get<ElementKind>(in);
  if (kind < ElementKind::Linear || kind > ElementKind::Strut)
    throw CheckpointError("unknown element kind " + std::to_string(static_cast<int>(kind)));
  const int material = get<int>(in);
  std::array<int, 2> nodes{};
  for (int& n : nodes) n = get<int>(in);
  std::unique_ptr<Element> el;
  if (kind == ElementKind::Jointed) {
    const int slaveEnd = get<int>(in);
    const int master = get<int>(in);
    if (slaveEnd != 0 && slaveEnd != 1) throw CheckpointError("bad slave end of a jointed element");
    if (master < 0 || master >= model.numNodes())
      throw CheckpointError("joint master out of range");
    el = std::make_unique<JointedElement>(readElement(in, model), slaveEnd, master);
  } else if (kind == ElementKind::Strut) {
    el = std::make_unique<InfillStrut>();
  } else {
    el = build(kind, model, material, nodes);
  }
  auto* c = dynamic_cast<Checkpoint*>(el.get());
  if (!c)
    throw CheckpointError("element type '" + el->typeName() +
                          "' cannot be read from a restart file");
  c->readState(in);
  if (el->nodes() != nodes || el->materialNumber() != material)
    throw CheckpointError("element data do not match its header");
  return el;
}

namespace {

void writeNodes(std::ostream& out, const Model& model) {
  putTag(out, "MODL");
  putCount(out, static_cast<std::size_t>(model.numNodes()));
  for (int n = 0; n < model.numNodes(); ++n) {
    putFixed(out, model.coord(n));
    putBool(out, model.hasCoord(n));
    for (int d = 0; d < kNodeDofs; ++d) {
      put(out, model.bound(n)[d]);
      put(out, model.force(n)[d]);
      put(out, model.disp(n)[d]);
      put(out, model.loadTable(n)[d]);
    }
  }
}

// The hinge laws of a material set: hardening, softening, the hinge site and
// the N-M interaction.
void writeHingeLaws(std::ostream& out, const MaterialSet& m) {
  putBool(out, m.hardening.has_value());
  if (m.hardening) {
    for (double x : {m.hardening->Mc, m.hardening->My, m.hardening->Kh1, m.hardening->Kh2})
      put(out, x);
    putBool(out, m.hardening->negative.has_value());
    if (const auto& n = m.hardening->negative)
      for (double x : {n->Mc, n->My, n->Kh1, n->Kh2}) put(out, x);
  }
  putBool(out, m.softening.has_value());
  if (m.softening) {
    for (double x : {m.softening->Mu, m.softening->Ks}) put(out, x);
    putOptional(out, m.softening->thetaR);
    put(out, m.softening->Mr);
    put(out, m.softening->pieceLength);
    putBool(out, m.softening->negative.has_value());
    if (const auto& n = m.softening->negative)
      for (double x : {n->first, n->second}) put(out, x);
  }
  put(out, m.hingeSite);
  putCount(out, m.interaction.size());
  for (const auto& [n, mu] : m.interaction)
    for (double x : {n, mu}) put(out, x);
}

void writeSection(std::ostream& out, const std::optional<RcSectionData>& section) {
  putBool(out, section.has_value());
  if (const auto& sec = section) {
    put(out, sec->shape);
    for (double x : {sec->b, sec->h, sec->fc, sec->fy, sec->Es, sec->fu, sec->eu,
                     sec->flangeWidth, sec->flangeDepth, sec->wall, sec->kept})
      put(out, x);
    putCount(out, sec->bars.size());
    for (const RebarLayer& r : sec->bars)
      for (double x : {r.depth, r.area}) put(out, x);
    putBool(out, sec->stirrups.has_value());
    if (const auto& st = sec->stirrups)
      for (double x : {st->area, st->spacing, st->fy}) put(out, x);
  }
}

void writeMaterials(std::ostream& out, const Model& model) {
  putTag(out, "MATS");
  putCount(out, model.materials().size());
  for (const auto& [number, m] : model.materials()) {
    put(out, number);
    put(out, m.number);
    putString(out, m.label);
    putString(out, m.elementType);
    for (double x : {m.E, m.nu, m.A, m.I, m.kappa, m.density}) put(out, x);
    putOptional(out, m.resEA);
    putOptional(out, m.resGA);
    putOptional(out, m.resEI);
    putBool(out, m.shear);
    put(out, m.kinematics);
    put(out, m.mass);
    writeHingeLaws(out, m);
    writeSection(out, m.section);
  }
}

void writeElementsAndJoints(std::ostream& out, const Model& model) {
  putTag(out, "ELEM");
  putCount(out, static_cast<std::size_t>(model.numElements()));
  for (const auto& el : model.elements()) {
    putBool(out, el != nullptr);
    if (el) writeElement(out, *el);
  }
  putTag(out, "JNTS");
  putCount(out, model.joints().size());
  for (const Joint& j : model.joints()) {
    put(out, j.master);
    put(out, j.slave);
    put(out, j.form);
  }
}

// Ground and member contact, and gravity.
void writeContact(std::ostream& out, const Model& model) {
  putTag(out, "GRND");
  putBool(out, model.ground().has_value());
  if (model.ground())
    for (double x : {model.ground()->y0, model.ground()->k, model.ground()->zeta,
                     model.ground()->mu, model.ground()->restitution})
      put(out, x);
  putBool(out, model.memberContact().has_value());
  if (model.memberContact())
    for (double x :
         {model.memberContact()->k, model.memberContact()->zeta, model.memberContact()->radius,
          model.memberContact()->restitution, model.memberContact()->mu})
      put(out, x);
  putFixed(out, model.gravity());
}

// Floor loads, nodal masses, the site.
void writeLoads(std::ostream& out, const Model& model) {
  putTag(out, "LOAD");
  putCount(out, model.elementLoads().size());
  for (const ElementLoad& l : model.elementLoads()) {
    put(out, l.element);
    putFixed(out, l.q);
    putBool(out, l.asMass);
  }
  for (int n = 0; n < model.numNodes(); ++n)
    for (double m : model.nodalMass(n)) put(out, m);
  putBool(out, model.site().has_value());
  if (const auto& site = model.site()) {
    for (double x : {site->xmin, site->xmax}) put(out, x);
    put(out, static_cast<int>(site->dir));
    putCount(out, site->objects.size());
    for (const ProtectedZone& z : site->objects) {
      putString(out, z.name);
      for (double x : {z.x1, z.x2, z.height, z.mass}) put(out, x);
    }
    for (double x : {site->flyrockMass, site->riskLevel, site->riskConfidence}) put(out, x);
  }
}

// Blasts and the forces their released elements left.
void writeBlasts(std::ostream& out, const Model& model) {
  putTag(out, "BLST");
  putCount(out, model.blasts().size());
  for (const Blast& b : model.blasts()) {
    put(out, b.time);
    put(out, b.release);
    putBool(out, b.done);
    putCount(out, b.elements.size());
    for (int e : b.elements) put(out, e);
  }
  putCount(out, model.releasedForces().size());
  for (const ReleasedForce& f : model.releasedForces()) {
    for (int n : f.nodes) put(out, n);
    for (int i = 0; i < kElemDofs; ++i) put(out, f.force[i]);
    put(out, f.start);
    put(out, f.duration);
  }
}

// The node records; returns the node count.
int readNodes(std::istream& in, Model& model) {
  expectTag(in, "MODL");
  // A node's record: its coordinates, a flag, and per dof a code, a force, a
  // displacement and a load table (89 bytes).
  constexpr std::size_t kNodeBytes = 2 * sizeof(double) + 1 + kNodeDofs * (2 * sizeof(int) + 2 * sizeof(double));
  const std::size_t count = getCount(in, kNodeBytes);
  if (count > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw CheckpointError("implausible node count " + std::to_string(count));
  const int nodes = static_cast<int>(count);
  model.resizeNodes(nodes);
  for (int n = 0; n < nodes; ++n) {
    Vec2 x;
    getFixed(in, x);
    if (getBool(in)) model.setCoord(n, x);
    for (int d = 0; d < kNodeDofs; ++d) {
      model.bound(n)[d] = get<int>(in);
      model.force(n)[d] = get<double>(in);
      model.disp(n)[d] = get<double>(in);
      model.loadTable(n)[d] = get<int>(in);
    }
  }
  return nodes;
}

void readHingeLaws(std::istream& in, MaterialSet& m) {
  if (getBool(in)) {
    HardeningData h;
    for (double* x : {&h.Mc, &h.My, &h.Kh1, &h.Kh2}) *x = get<double>(in);
    if (getBool(in)) {
      HardeningValues n;
      for (double* x : {&n.Mc, &n.My, &n.Kh1, &n.Kh2}) *x = get<double>(in);
      h.negative = n;
    }
    m.hardening = h;
  }
  if (getBool(in)) {
    SofteningData s;
    for (double* x : {&s.Mu, &s.Ks}) *x = get<double>(in);
    s.thetaR = getOptional(in);
    s.Mr = get<double>(in);
    s.pieceLength = get<double>(in);
    if (getBool(in)) {
      const double mu = get<double>(in), ks = get<double>(in);
      s.negative = std::make_pair(mu, ks);
    }
    m.softening = s;
  }
  m.hingeSite = get<HingeSite>(in);
  const std::size_t pairs = getCount(in);
  for (std::size_t i = 0; i < pairs; ++i) {
    const double n = get<double>(in), mu = get<double>(in);
    m.interaction.emplace_back(n, mu);
  }
}

void readSection(std::istream& in, MaterialSet& m) {
  if (!getBool(in)) return;
  RcSectionData sec;
  sec.shape = get<SectionShapeKind>(in);
  if (static_cast<int>(sec.shape) < 0 || static_cast<int>(sec.shape) > 3)
    throw CheckpointError("material " + std::to_string(m.number) + ": unknown section shape");
  for (double* x : {&sec.b, &sec.h, &sec.fc, &sec.fy, &sec.Es, &sec.fu, &sec.eu,
                    &sec.flangeWidth, &sec.flangeDepth, &sec.wall, &sec.kept})
    *x = get<double>(in);
  const std::size_t layers = getCount(in);
  for (std::size_t i = 0; i < layers; ++i) {
    RebarLayer r;
    r.depth = get<double>(in);
    r.area = get<double>(in);
    sec.bars.push_back(r);
  }
  if (getBool(in)) {
    Stirrups st;
    for (double* x : {&st.area, &st.spacing, &st.fy}) *x = get<double>(in);
    sec.stirrups = st;
  }
  m.section = sec;
}

void readMaterials(std::istream& in, Model& model) {
  expectTag(in, "MATS");
  const std::size_t mats = getCount(in);
  for (std::size_t k = 0; k < mats; ++k) {
    const int key = get<int>(in);
    MaterialSet m;
    m.number = get<int>(in);
    m.label = getString(in);
    m.elementType = getString(in);
    for (double* x : {&m.E, &m.nu, &m.A, &m.I, &m.kappa, &m.density}) *x = get<double>(in);
    m.resEA = getOptional(in);
    m.resGA = getOptional(in);
    m.resEI = getOptional(in);
    m.shear = getBool(in);
    m.kinematics = get<Kinematics>(in);
    m.mass = get<MassType>(in);
    readHingeLaws(in, m);
    readSection(in, m);
    try {
      deriveSectionLaws(m);
    } catch (const std::invalid_argument& e) {
      throw CheckpointError(std::string("material ") + std::to_string(m.number) + ": " + e.what());
    }
    model.materials()[key] = std::move(m);
  }
}

void readElementsAndJoints(std::istream& in, Model& model, int nodes) {
  expectTag(in, "ELEM");
  const std::size_t elements = getCount(in);
  for (std::size_t e = 0; e < elements; ++e) {
    std::unique_ptr<Element> el;
    if (getBool(in)) el = readElement(in, model);
    model.elements().push_back(std::move(el));
  }
  expectTag(in, "JNTS");
  const std::size_t joints = getCount(in);
  for (std::size_t k = 0; k < joints; ++k) {
    Joint j;
    j.master = get<int>(in);
    j.slave = get<int>(in);
    j.form = get<JointForm>(in);
    if (j.master < 0 || j.master >= nodes || j.slave < 0 || j.slave >= nodes)
      throw CheckpointError("joint node out of range");
    model.joints().push_back(j);
  }
}

void readContact(std::istream& in, Model& model) {
  expectTag(in, "GRND");
  if (getBool(in)) {
    Ground g;
    for (double* x : {&g.y0, &g.k, &g.zeta, &g.mu, &g.restitution}) *x = get<double>(in);
    model.ground() = g;
  }
  if (getBool(in)) {
    MemberContactData c;
    for (double* x : {&c.k, &c.zeta, &c.radius, &c.restitution, &c.mu}) *x = get<double>(in);
    model.memberContact() = c;
  }
  getFixed(in, model.gravity());
}

void readSite(std::istream& in, Model& model) {
  if (!getBool(in)) return;
  Site site;
  for (double* x : {&site.xmin, &site.xmax}) *x = get<double>(in);
  const int dir = get<int>(in);
  if (dir < 0 || dir > static_cast<int>(FallDirection::Down))
    throw CheckpointError("site with an unknown fall direction");
  site.dir = static_cast<FallDirection>(dir);
  const std::size_t zones = getCount(in);
  for (std::size_t k = 0; k < zones; ++k) {
    ProtectedZone z;
    z.name = getString(in);
    for (double* x : {&z.x1, &z.x2, &z.height, &z.mass}) *x = get<double>(in);
    site.objects.push_back(std::move(z));
  }
  for (double* x : {&site.flyrockMass, &site.riskLevel, &site.riskConfidence})
    *x = get<double>(in);
  model.site() = site;
}

void readLoads(std::istream& in, Model& model, int nodes) {
  expectTag(in, "LOAD");
  const std::size_t loads = getCount(in);
  for (std::size_t k = 0; k < loads; ++k) {
    ElementLoad l;
    l.element = get<int>(in);
    getFixed(in, l.q);
    l.asMass = getBool(in);
    if (l.element < 0 || l.element >= model.numElements())
      throw CheckpointError("element load on an element out of range");
    model.elementLoads().push_back(l);
  }
  for (int n = 0; n < nodes; ++n)
    for (double& m : model.nodalMass(n)) m = get<double>(in);
  readSite(in, model);
}

void readBlasts(std::istream& in, Model& model, int nodes) {
  expectTag(in, "BLST");
  const std::size_t blasts = getCount(in);
  for (std::size_t k = 0; k < blasts; ++k) {
    Blast b;
    b.time = get<double>(in);
    b.release = get<double>(in);
    b.done = getBool(in);
    b.elements.resize(getCount(in));
    for (int& e : b.elements) {
      e = get<int>(in);
      if (e < 0 || e >= model.numElements())
        throw CheckpointError("blast of an element out of range");
    }
    model.blasts().push_back(std::move(b));
  }
  const std::size_t released = getCount(in);
  for (std::size_t k = 0; k < released; ++k) {
    ReleasedForce f;
    for (int& n : f.nodes) {
      n = get<int>(in);
      if (n < 0 || n >= nodes) throw CheckpointError("released force on a node out of range");
    }
    for (int i = 0; i < kElemDofs; ++i) f.force[i] = get<double>(in);
    f.start = get<double>(in);
    f.duration = get<double>(in);
    model.releasedForces().push_back(f);
  }
}

}  // namespace

void writeModel(std::ostream& out, const Model& model) {
  writeNodes(out, model);
  writeMaterials(out, model);
  writeElementsAndJoints(out, model);
  writeContact(out, model);
  writeLoads(out, model);
  writeBlasts(out, model);
  put(out, model.topologyVersion());
}

Model readModel(std::istream& in, int minTopologyVersion) {
  Model model;
  const int nodes = readNodes(in, model);
  readMaterials(in, model);
  readElementsAndJoints(in, model, nodes);
  readContact(in, model);
  readLoads(in, model, nodes);
  readBlasts(in, model, nodes);
  const int version = get<int>(in);
  while (model.topologyVersion() < std::max(version, minTopologyVersion)) model.bumpTopology();
  return model;
}

}  // namespace c2d
