#pragma once
// The model in a restart file (core/io/Checkpoint.h): nodes with their restraint
// codes, loads, prescribed values and load tables, material sets, elements
// (type, construction data and complete state), joints, ground and gravity:
// the model as it is now, after any HINGE2JOINT or MESH re-entry.
//
// An element is written as its kind, material number and nodes, then (a
// jointed element) its slave end, master node and the wrapped element, then
// its Checkpoint data. Reading builds the element of that kind from the
// restored model's material set and node coordinates and lets it read its
// data, which overwrites everything the constructor computed.
#include <istream>
#include <memory>
#include <ostream>

#include "core/Element.h"
#include "core/Model.h"

namespace c2d {

// Throws CheckpointError for an element that cannot be written (no Checkpoint ability).
void writeElement(std::ostream& out, const Element& element);
// Throws CheckpointError on bad data or an element the model cannot build.
std::unique_ptr<Element> readElement(std::istream& in, const Model& model);

void writeModel(std::ostream& out, const Model& model);
// The model as written, with a topology version of at least minTopologyVersion
// (so that everything holding a pattern of another model rebuilds it).
Model readModel(std::istream& in, int minTopologyVersion);

}  // namespace c2d
