#pragma once
// What a restart file was computed for: hashes of the model as the deck's
// mesh input built it (before any solution command changed it), part by part,
// so that REST of a file written by another deck is refused with an error
// naming what differs instead of continuing someone else's run.
#include <cstdint>
#include <istream>
#include <ostream>
#include <string>

#include "core/Model.h"

namespace c2d {

struct ModelFingerprint {
  std::uint64_t coordinates = 0;  // node count and coordinates
  std::uint64_t elements = 0;     // element count, nodes and material numbers
  std::uint64_t materials = 0;    // every material set's data
  std::uint64_t boundary = 0;     // restraint codes and joints
  std::uint64_t loads = 0;  // forces, prescribed values, load tables, floor loads, gravity, contact
  std::uint64_t masses = 0;  // nodal masses (MASS) and floor loads carried as mass
  std::uint64_t site = 0;    // the debris site (SITE)

  static ModelFingerprint of(const Model& model);
  // The parts that differ, e.g. "node coordinates, nodal loads"; empty if none.
  std::string differences(const ModelFingerprint& other) const;

  void write(std::ostream& out) const;
  static ModelFingerprint read(std::istream& in);  // throws CheckpointError
};

}  // namespace c2d
