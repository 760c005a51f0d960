#pragma once
// Support for the tests of mesh commands: a one-problem deck's mesh applied
// to a model (control record 0 0 0 2 3 2 unless given), with its echo; a
// beam's and a cantilever's mesh, and a material of hand-given laws.
#include <ostream>
#include <string>

#include "macro/deck/DeckParser.h"
#include "macro/mesh/MeshBinder.h"
#include "macro/mesh/ParseDeck.h"
#include "tests/unit/DeckTestSupport.h"

namespace c2d::testing {

inline std::string meshDeck(const std::string& mesh, const std::string& control = "0 0 0 2 3 2") {
  return "FEAP * * test\n" + control + "\n" + mesh + "END\nSTOP\n";
}

// The mesh of a one-problem deck applied to model (params: the deck's
// parameters, none when null; the mesh may lack elements).
inline void bindMesh(Model& model, const std::string& mesh, std::ostream* echo = nullptr,
                     const std::string& control = "0 0 0 2 3 2", Parameters* params = nullptr) {
  const Deck d = parseDeckText(meshDeck(mesh, control), "mesh.inp");
  const Problem& pr = std::get<Problem>(d.items.at(0));
  Parameters local;
  MeshBinder binder(model, params ? *params : local, echo);
  binder.setControl(pr.control);
  binder.apply(pr.mesh);
  binder.finish(pr.meshEnd.loc, pr.meshEnd.lineText());
}

inline Model buildMesh(const std::string& mesh, std::ostream* echo = nullptr,
                       const std::string& control = "0 0 0 2 3 2", Parameters* params = nullptr) {
  Model model;
  bindMesh(model, mesh, echo, control, params);
  return model;
}

// A DeckError at mesh.inp:line:col whose message holds msg.
inline void expectMeshError(const std::string& mesh, int line, int col, const std::string& msg) {
  expectDeckError([&] { buildMesh(mesh); }, "mesh.inp", line, col, msg);
}

// MATErial 1, a FRAMe of hand-given laws: bilinear hardening, linear softening
// and an interaction curve.
inline const char* const kHand =
    "MATE,1 beam\n FRAMe\n ELAStic ISOTropic 30e6 0.2\n CROSs SECTion 0.12 1.6e-3\n"
    " DENSity,,2.5\n HARDening BILInear 40 60 1000 100\n SOFTening LINEar 70 -500 0.3 2\n"
    " INTEraction CURVe -2000 90 0 70 500 20\n\n";

// Lines 3-14 of a mesh deck: three elements along x (nodes 1-4, 1 m each) of
// a FRAMe of given resultant stiffnesses; the tested commands follow from line 15.
inline const std::string kBeamMesh =
    "COOR\n 1 1 0 0\n 4 0 3 0\n\n"
    "MATErial,1\n FRAMe\n RESUltant STIFfness 1e7 1e7 1e4\n\n"
    "ELEM\n 1 1 1 1 2\n 3 0 1 3 4\n\n";

// A column of material 1 from node 1 at the origin to node 4 at 3 m up (nodes
// and three elements generated) after the given MATErial records; no
// boundary conditions.
inline std::string cantilever(const std::string& material) {
  return "COOR\n 1 1 0 0\n 4 0 0 3\n\n" + material + "ELEM\n 1 1 1 1 2\n 3 1 1 3 4\n\n";
}

}  // namespace c2d::testing
