#include "macro/draws/CounterRandom.h"

#include <cctype>
#include <string>

namespace c2d {

namespace {

std::uint64_t splitMix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

}  // namespace

double counterUniform(std::uint64_t seed, std::uint64_t sample, std::uint64_t stream,
                      std::uint64_t index) {
  std::uint64_t k = splitMix(seed);
  k = splitMix(k ^ sample);
  k = splitMix(k ^ stream);
  k = splitMix(k ^ index);
  return (static_cast<double>(k >> 11) + 0.5) * 0x1.0p-53;
}

std::uint64_t streamOf(std::string_view name) {
  std::uint64_t h = 14695981039346656037ull;
  for (char c : name) {
    h ^= static_cast<unsigned char>(std::tolower(static_cast<unsigned char>(c)));
    h *= 1099511628211ull;
  }
  return h;
}

std::uint64_t drawnStream(std::string_view name) {
  const std::uint64_t s = streamOf(name);
  for (const char* own : {"jitter", "jitter.dt", "detonator"})
    if (s == streamOf(own)) return streamOf("drawn." + std::string(name));
  return s;
}

}  // namespace c2d
