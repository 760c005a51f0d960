#include "solvers/RestartFile.h"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <sstream>

#include "core/InputFile.h"
#include "core/io/AtomicFile.h"
#include "core/io/Checkpoint.h"
#include "elements/ModelCheckpoint.h"

namespace c2d {

namespace {

constexpr char kMagic[8] = {'C', '2', 'D', 'R', 'S', 'T', '\r', '\n'};
constexpr std::uint32_t kByteOrder = 0x01020304;
constexpr std::size_t kHeaderBytes = sizeof kMagic + 4 + 4 + 8;

std::uint64_t fnv1a(const std::string& bytes) {
  std::uint64_t h = 14695981039346656037ull;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

}  // namespace

void saveRestart(const std::filesystem::path& file, const Model& model, const Analysis& analysis,
                 const std::string& extra, const ModelFingerprint& input) {
  std::ostringstream payload(std::ios::binary);
  input.write(payload);
  writeModel(payload, model);
  analysis.writeState(payload);
  checkpoint::putTag(payload, "USER");
  checkpoint::putString(payload, extra);
  checkpoint::putTag(payload, "DONE");
  const std::string body = payload.str();

  AtomicFile out(file);
  std::ostream& os = out.stream();
  os.write(kMagic, sizeof kMagic);
  checkpoint::put<std::uint32_t>(os, kRestartVersion);
  checkpoint::put<std::uint32_t>(os, kByteOrder);
  checkpoint::put<std::uint64_t>(os, body.size());
  os.write(body.data(), static_cast<std::streamsize>(body.size()));
  checkpoint::put<std::uint64_t>(os, fnv1a(body));
  out.commit();
}

std::string loadRestart(const std::filesystem::path& file, Model& model, Analysis& analysis,
                        const ModelFingerprint* fingerprint) {
  const std::string name = "restart file '" + file.string() + "': ";
  // The file's size is checked against the model before it is read: a save
  // holds far less than 64 kB per node and element (the model may have grown
  // by joints and pieces since the deck built it).
  const std::uintmax_t items = static_cast<std::uintmax_t>(model.numNodes() + model.numElements());
  const std::uintmax_t limit = (std::uintmax_t{64} << 20) + items * (std::uintmax_t{64} << 10);
  std::string bytes;
  try {
    bytes = readRegularFile(file, limit);
  } catch (const UnfitInputFile& e) {
    throw CheckpointError(name + e.what() + " (the model has " + std::to_string(model.numNodes()) +
                          " nodes, " + std::to_string(model.numElements()) + " elements)");
  } catch (const IoError& e) {
    throw CheckpointError(name + "cannot be opened (" + e.what() + ")");
  }

  if (bytes.size() < sizeof kMagic || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
    throw CheckpointError(name + "not a collapse2d restart file (no restart header)");
  if (bytes.size() < kHeaderBytes)
    throw CheckpointError(name + "truncated in its header (" + std::to_string(bytes.size()) + " bytes)");
  std::uint32_t version = 0, order = 0;
  std::uint64_t size = 0;
  std::memcpy(&version, bytes.data() + 8, 4);
  std::memcpy(&order, bytes.data() + 12, 4);
  std::memcpy(&size, bytes.data() + 16, 8);
  if (order != kByteOrder)
    throw CheckpointError(name + "written on a machine of another byte order");
  if (version != kRestartVersion)
    throw CheckpointError(name + "format version " + std::to_string(version) +
                          ", this program reads version " + std::to_string(kRestartVersion));
  const std::uint64_t expected = kHeaderBytes + size + 8;
  if (size > bytes.size() || bytes.size() != expected)
    throw CheckpointError(name + (bytes.size() < expected ? "truncated" : "has trailing data") +
                          " (" + std::to_string(bytes.size()) + " bytes, the header says " +
                          std::to_string(expected) + ")");
  const std::string body = bytes.substr(kHeaderBytes, static_cast<std::size_t>(size));
  std::uint64_t sum = 0;
  std::memcpy(&sum, bytes.data() + kHeaderBytes + size, 8);
  if (sum != fnv1a(body)) throw CheckpointError(name + "corrupted (checksum mismatch)");

  std::istringstream is(body, std::ios::binary);
  try {
    const ModelFingerprint saved = ModelFingerprint::read(is);
    if (fingerprint) {
      const std::string differs = fingerprint->differences(saved);
      if (!differs.empty())
        throw CheckpointError("written for another model: the " + differs +
                              " differ from this deck's");
    }
    Model restored = readModel(is, model.topologyVersion() + 1);
    model = std::move(restored);
    analysis.readState(is);
    checkpoint::expectTag(is, "USER");
    std::string extra = checkpoint::getString(is);
    checkpoint::expectTag(is, "DONE");
    if (is.peek() != std::char_traits<char>::eof()) throw CheckpointError("data after the end");
    return extra;
  } catch (const CheckpointError& e) {
    throw CheckpointError(name + e.what());
  }
}

}  // namespace c2d
