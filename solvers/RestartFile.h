#pragma once
// Restart files (deck: SAVE[,name] / REST[,name]): the full analysis state, so
// that a run restarted from a save repeats the uninterrupted run bit for bit.
//
// Layout (binary, every number in the byte order of the writing machine):
//   magic       8 bytes  "C2DRST\r\n" (the CR LF catches text-mode mangling)
//   version     uint32   kRestartVersion
//   byte order  uint32   0x01020304 as written
//   size        uint64   payload bytes
//   payload              the fingerprint of the deck's model (ModelFingerprint),
//                        the model (elements/ModelCheckpoint), the analysis
//                        (Analysis::writeState), the caller's section
//   checksum    uint64   FNV-1a of the payload
// Reading checks all of them before it changes anything: a truncated,
// corrupted or foreign file is an error naming the file, never garbage.
// Written with core/io/AtomicFile (a temporary, renamed when complete).
// Read only when it is a regular file no larger than the model can explain
// (core/InputFile.h), every count checked against the bytes left.
#include <filesystem>
#include <string>

#include "core/Model.h"
#include "solvers/Analysis.h"
#include "solvers/ModelFingerprint.h"

namespace c2d {

inline constexpr unsigned kRestartVersion = 24;  // 17: infill struts; 18: section shapes; 19: rigid end zones; 20: the site's zones and fall; 21: shear failures counted; 22: weakened sections' kept share; 23: joints at rigid zones' faces; 24: ground impacts' owed energy

// Writes the committed state: call Analysis::commit() first. `extra` is the
// caller's own section (opaque here); `input` the fingerprint of the model as
// the deck's mesh input built it. Throws std::runtime_error on I/O failure.
void saveRestart(const std::filesystem::path& file, const Model& model, const Analysis& analysis,
                 const std::string& extra, const ModelFingerprint& input = {});

// Replaces `model` (in place: the analysis keeps referring to it) and the
// analysis state by the saved ones; returns the caller's section. With
// `expected` (the fingerprint of the reading deck's model), a file written for
// another model is refused, naming what differs. Throws CheckpointError with a
// message that names the file.
std::string loadRestart(const std::filesystem::path& file, Model& model, Analysis& analysis,
                        const ModelFingerprint* expected = nullptr);

}  // namespace c2d
