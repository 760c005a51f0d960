#pragma once
// [ext] The random numbers of an ensemble (ENSEmble): counter-based, each a
// pure function of (seed, sample, stream, index), never the state of a
// generator. So a sample's draws are the same whichever runs a process makes,
// in whatever order (shards, `run -j`, reruns repeat them bit for bit), and
// every plan of a study sees the same draws in its sample k (common random
// numbers: plans compared pair by pair).
//
// The key is the four words mixed through SplitMix64's finalizer in turn (a
// bijection of 64-bit words with full avalanche); the top 53 bits of the result
// give a uniform number in (0, 1), never 0 or 1.
#include <cstdint>
#include <string_view>

namespace c2d {

// A uniform number in (0, 1).
double counterUniform(std::uint64_t seed, std::uint64_t sample, std::uint64_t stream,
                      std::uint64_t index);

// The stream of a name (a drawn parameter, "jitter", "detonator"): FNV-1a of its
// lower-case letters, so that streams do not depend on the order of the records.
std::uint64_t streamOf(std::string_view name);

// The stream of a drawn parameter: streamOf(name), unless that is a stream of
// the program's own draws (the JITTer's "jitter" and "jitter.dt", the
// DETOnators' "detonator"): then streamOf("drawn." + name), so that a
// parameter named detonator is not the detonators' scatter drawn again.
std::uint64_t drawnStream(std::string_view name);

}  // namespace c2d
