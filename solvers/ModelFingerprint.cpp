#include "solvers/ModelFingerprint.h"

#include <cstring>

#include "core/io/Checkpoint.h"
#include "elements/ElementFactory.h"

namespace c2d {

namespace {

// FNV-1a over the raw bytes of the values fed to it: the same deck gives the
// same bits, so equal inputs hash equal and any changed number changes the hash.
class Hash {
 public:
  template <class T>
  Hash& add(const T& value) {
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    for (unsigned char c : bytes) {
      h_ ^= c;
      h_ *= 1099511628211ull;
    }
    return *this;
  }
  Hash& add(const std::string& s) {
    add(s.size());
    for (char c : s) add(c);
    return *this;
  }
  std::uint64_t value() const { return h_; }

 private:
  std::uint64_t h_ = 14695981039346656037ull;
};

// Per node: coordinates, the restrained dofs, nodal loads and masses.
void hashNodes(const Model& model, Hash& coords, Hash& boundary, Hash& loads, Hash& masses) {
  coords.add(model.numNodes());
  for (int n = 0; n < model.numNodes(); ++n) {
    coords.add(model.hasCoord(n));
    coords.add(model.coord(n).x()).add(model.coord(n).y());
    for (int d = 0; d < kNodeDofs; ++d) {
      boundary.add(model.bound(n)[d] != 0);
      loads.add(model.force(n)[d]).add(model.disp(n)[d]).add(model.loadTable(n)[d]);
      masses.add(model.nodalMass(n)[d]);
    }
  }
}

void hashConnectivity(const Model& model, Hash& elements) {
  elements.add(model.numElements());
  for (int e = 0; e < model.numElements(); ++e) {
    if (!model.hasElement(e)) {
      elements.add(-1);
      continue;
    }
    const Element& el = model.element(e);
    elements.add(el.nodes()[0]).add(el.nodes()[1]).add(el.materialNumber());
    // Rigid end zones (RIGId), only where given: other decks' fingerprints stay.
    if (const auto o = rigidOffsets(el); o[0] > 0 || o[1] > 0) elements.add(o[0]).add(o[1]);
  }
}

void hashMaterial(Hash& materials, int number, const MaterialSet& m) {
  materials.add(number).add(m.elementType);
  for (double x : {m.E, m.nu, m.A, m.I, m.kappa, m.EA(), m.GA(), m.EI(), m.density, m.dampingA1})
    materials.add(x);
  materials.add(m.shear).add(m.kinematics).add(m.mass);
  materials.add(m.hardening.has_value());
  if (m.hardening)
    for (double x : {m.hardening->Mc, m.hardening->My, m.hardening->Kh1, m.hardening->Kh2})
      materials.add(x);
  materials.add(m.softening.has_value());
  if (m.softening)
    materials.add(m.softening->Mu)
        .add(m.softening->Ks)
        .add(m.softening->thetaR.value_or(-1))
        .add(m.softening->Mr)
        .add(m.softening->pieceLength);
  // Negative moments' laws, hinge site, interaction curve, RC section data.
  if (m.hardening && m.hardening->negative)
    for (double x : {m.hardening->negative->Mc, m.hardening->negative->My,
                     m.hardening->negative->Kh1, m.hardening->negative->Kh2})
      materials.add(x);
  if (m.softening && m.softening->negative)
    materials.add(m.softening->negative->first).add(m.softening->negative->second);
  materials.add(m.hingeSite == HingeSite::Ends);
  for (const auto& [n, mu] : m.interaction) materials.add(n).add(mu);
  if (const auto& sec = m.section) {
    materials.add(static_cast<int>(sec->shape));
    for (double x : {sec->b, sec->h, sec->fc, sec->fy, sec->Es, sec->fu, sec->eu,
                     sec->flangeWidth, sec->flangeDepth, sec->wall})
      materials.add(x);
    for (const RebarLayer& r : sec->bars) materials.add(r.depth).add(r.area);
  }
}

// Gravity, ground and member contact, floor loads.
void hashLoads(const Model& model, Hash& loads, Hash& masses) {
  loads.add(model.gravity().x()).add(model.gravity().y()).add(model.ground().has_value());
  if (model.ground())
    loads.add(model.ground()->y0)
        .add(model.ground()->k)
        .add(model.ground()->zeta)
        .add(model.ground()->mu)
        .add(model.ground()->restitution);
  loads.add(model.memberContact().has_value());
  if (const auto& c = model.memberContact())
    loads.add(c->k).add(c->zeta).add(c->radius).add(c->restitution).add(c->mu);
  // Floor loads (QLOAd): their load, and their mass when they carry it.
  loads.add(model.elementLoads().size());
  for (const ElementLoad& q : model.elementLoads()) {
    loads.add(q.element).add(q.q.x()).add(q.q.y());
    masses.add(q.asMass);
    if (q.asMass) masses.add(q.element).add(q.q.x()).add(q.q.y());
  }
}

void hashSite(const Model& model, Hash& site) {
  site.add(model.site().has_value());
  if (const auto& st = model.site()) {
    site.add(st->xmin).add(st->xmax).add(static_cast<int>(st->dir)).add(st->objects.size());
    for (const ProtectedZone& z : st->objects)
      site.add(z.name).add(z.x1).add(z.x2).add(z.height).add(z.mass);
    site.add(st->flyrockMass).add(st->riskLevel).add(st->riskConfidence);
  }
}

}  // namespace

ModelFingerprint ModelFingerprint::of(const Model& model) {
  Hash coords, elements, materials, boundary, loads, masses, site;
  hashNodes(model, coords, boundary, loads, masses);
  hashConnectivity(model, elements);
  for (const auto& [number, m] : model.materials()) hashMaterial(materials, number, m);
  boundary.add(model.joints().size());
  for (const Joint& j : model.joints()) boundary.add(j.master).add(j.slave);
  hashLoads(model, loads, masses);
  hashSite(model, site);
  // The blast plan: element sets, times, release times.
  elements.add(model.blasts().size());
  for (const Blast& b : model.blasts()) {
    elements.add(b.time).add(b.release).add(b.elements.size());
    for (int e : b.elements) elements.add(e);
  }
  return {coords.value(), elements.value(), materials.value(), boundary.value(),
          loads.value(),  masses.value(),   site.value()};
}

std::string ModelFingerprint::differences(const ModelFingerprint& o) const {
  std::string out;
  auto note = [&](bool differs, const char* what) {
    if (!differs) return;
    if (!out.empty()) out += ", ";
    out += what;
  };
  note(coordinates != o.coordinates, "node coordinates");
  note(elements != o.elements, "element connectivity, material numbers or blasts");
  note(materials != o.materials, "material data");
  note(boundary != o.boundary, "boundary codes or joints");
  note(loads != o.loads,
       "loads (forces, prescribed values, load tables, floor loads, gravity, contact)");
  note(masses != o.masses, "masses (MASS, floor loads carried as mass)");
  note(site != o.site, "site (SITE)");
  return out;
}

void ModelFingerprint::write(std::ostream& out) const {
  using namespace checkpoint;
  putTag(out, "FPRT");
  for (std::uint64_t x : {coordinates, elements, materials, boundary, loads, masses, site})
    put(out, x);
}

ModelFingerprint ModelFingerprint::read(std::istream& in) {
  using namespace checkpoint;
  expectTag(in, "FPRT");
  ModelFingerprint f;
  for (std::uint64_t* x :
       {&f.coordinates, &f.elements, &f.materials, &f.boundary, &f.loads, &f.masses, &f.site})
    *x = get<std::uint64_t>(in);
  return f;
}

}  // namespace c2d
