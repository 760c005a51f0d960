#include "core/io/Checkpoint.h"

#include <cstring>

namespace c2d::checkpoint {

void putBool(std::ostream& out, bool v) { put<std::uint8_t>(out, v ? 1 : 0); }

bool getBool(std::istream& in) {
  const auto v = get<std::uint8_t>(in);
  if (v > 1) throw CheckpointError("bad boolean value " + std::to_string(v));
  return v == 1;
}

void putCount(std::ostream& out, std::size_t n) { put<std::uint64_t>(out, n); }

namespace {

// The bytes left in a seekable stream; -1 when it cannot tell.
std::streamoff bytesLeft(std::istream& in) {
  const std::streampos here = in.tellg();
  if (here == std::streampos(-1)) return -1;
  in.seekg(0, std::ios::end);
  const std::streampos end = in.tellg();
  in.seekg(here);
  if (end == std::streampos(-1) || !in) {
    in.clear();
    in.seekg(here);
    return -1;
  }
  return end - here;
}

}  // namespace

std::size_t getCount(std::istream& in, std::size_t minBytesEach) {
  const auto n = get<std::uint64_t>(in);
  if (n > kMaxCount) throw CheckpointError("implausible size " + std::to_string(n));
  const std::streamoff left = bytesLeft(in);
  if (left >= 0 && minBytesEach > 0 &&
      n > static_cast<std::uint64_t>(left) / static_cast<std::uint64_t>(minBytesEach))
    throw CheckpointError("a count of " + std::to_string(n) + " items where " +
                          std::to_string(left) + " bytes are left");
  return static_cast<std::size_t>(n);
}

void putString(std::ostream& out, const std::string& s) {
  putCount(out, s.size());
  out.write(s.data(), static_cast<std::streamsize>(s.size()));
}

std::string getString(std::istream& in) {
  std::string s(getCount(in), '\0');
  if (!s.empty() && !in.read(s.data(), static_cast<std::streamsize>(s.size())))
    throw CheckpointError("unexpected end of data");
  return s;
}

void putDoubles(std::ostream& out, const double* p, std::size_t n) {
  out.write(reinterpret_cast<const char*>(p), static_cast<std::streamsize>(n * sizeof(double)));
}

void getDoubles(std::istream& in, double* p, std::size_t n) {
  if (n && !in.read(reinterpret_cast<char*>(p), static_cast<std::streamsize>(n * sizeof(double))))
    throw CheckpointError("unexpected end of data");
}

void putVector(std::ostream& out, const Eigen::VectorXd& v) {
  putCount(out, static_cast<std::size_t>(v.size()));
  putDoubles(out, v.data(), static_cast<std::size_t>(v.size()));
}

Eigen::VectorXd getVector(std::istream& in) {
  const std::size_t n = getCount(in);
  Eigen::VectorXd v(static_cast<Eigen::Index>(n));
  getDoubles(in, v.data(), n);
  return v;
}

void putOptional(std::ostream& out, const std::optional<double>& v) {
  putBool(out, v.has_value());
  if (v) put(out, *v);
}

std::optional<double> getOptional(std::istream& in) {
  if (!getBool(in)) return std::nullopt;
  return get<double>(in);
}

void putTag(std::ostream& out, const char (&tag)[5]) { out.write(tag, 4); }

void expectTag(std::istream& in, const char (&tag)[5]) {
  char got[4] = {};
  if (!in.read(got, 4)) throw CheckpointError(std::string("unexpected end of data before section '") + tag + "'");
  if (std::memcmp(got, tag, 4) != 0)
    throw CheckpointError(std::string("section '") + tag + "' expected, the data is out of place");
}

}  // namespace c2d::checkpoint
