#pragma once
// Builds the element a material set asks for.
#include <array>
#include <memory>

#include "core/Element.h"
#include "core/MaterialSet.h"

namespace c2d {

// FRAMe + SMALl, elastic: LinearFrame (Timoshenko with SHEAr ON, Euler-Bernoulli with OFF);
// FRAMe + SMALl with HARDening and/or SOFTening: InelasticFrame (Timoshenko, hinge);
// FRAMe + FINIte: ReissnerFrame (geometrically exact).
// x1, x2 are the reference coordinates of the two nodes; offsets the rigid end
// zones at them (elements/RigidEnds.h; std::invalid_argument when they leave
// no flexible length).
std::unique_ptr<Element> makeElement(const MaterialSet& mat, const std::array<int, 2>& nodes,
                                     const Vec2& x1, const Vec2& x2,
                                     const std::array<double, 2>& offsets = {0.0, 0.0});

// The rigid end zones of a frame element (inside its joint wrappers); zero for none.
std::array<double, 2> rigidOffsets(const Element& e);

}  // namespace c2d
