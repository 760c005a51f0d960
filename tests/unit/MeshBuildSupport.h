#pragma once
// Support for the tests of mesh commands: a one-problem deck's mesh applied
// to a new model (control record 0 0 0 2 3 2 unless given), with its echo.
#include <ostream>
#include <string>

#include "macro/deck/DeckParser.h"
#include "macro/deck/MeshBinder.h"
#include "tests/unit/DeckTestSupport.h"

namespace c2d::testing {

inline std::string meshDeck(const std::string& mesh, const std::string& control = "0 0 0 2 3 2") {
  return "FEAP * * test\n" + control + "\n" + mesh + "END\nSTOP\n";
}

inline Model buildMesh(const std::string& mesh, std::ostream* echo = nullptr,
                       const std::string& control = "0 0 0 2 3 2") {
  const Deck d = parseDeckText(meshDeck(mesh, control), "mesh.inp");
  const Problem& pr = std::get<Problem>(d.items.at(0));
  Parameters params;
  Model model;
  MeshBinder binder(model, params, echo);
  binder.setControl(pr.control);
  binder.apply(pr.mesh);
  binder.finish(pr.meshEnd.loc, pr.meshEnd.lineText());
  return model;
}

// A DeckError at mesh.inp:line:col whose message holds msg.
inline void expectMeshError(const std::string& mesh, int line, int col, const std::string& msg) {
  expectDeckError([&] { buildMesh(mesh); }, "mesh.inp", line, col, msg);
}

}  // namespace c2d::testing
