#pragma once
// Restart files: the ability of an object to write its complete state as raw
// binary data and to read it back, so that a restarted run continues bit for
// bit. Doubles are written as their bytes (no decimal conversion), in the byte
// order of the machine that wrote them (the restart file's header records it).
//
// Checkpoint is an extra ability of an element (not part of the element
// contract, core/Element.h): elements/ModelCheckpoint writes an element's type
// and construction data, rebuilds it from those, then calls readState().
// writeState() writes everything that is not a pure function of the
// construction data: history (committed and trial), and the derived constants,
// so that the element read back is the one written, whatever its constructor
// computes.
//
// The helpers below throw CheckpointError on a short read or an implausible
// size; the code that opens the file adds its name to the message.
#include <Eigen/Core>
#include <cstdint>
#include <istream>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace c2d {

class CheckpointError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Checkpoint {
 public:
  virtual ~Checkpoint() = default;
  virtual void writeState(std::ostream& out) const = 0;
  // Reads what writeState() wrote into an object built from the same
  // construction data; throws CheckpointError on bad data.
  virtual void readState(std::istream& in) = 0;
};

namespace checkpoint {

// Largest element count a size field may claim (guards against allocating
// from a corrupted size before the data runs out).
inline constexpr std::uint64_t kMaxCount = std::uint64_t{1} << 32;

template <class T>
void put(std::ostream& out, const T& v) {
  static_assert(std::is_arithmetic_v<T> || std::is_enum_v<T>, "raw values only");
  out.write(reinterpret_cast<const char*>(&v), sizeof(T));
}

template <class T>
T get(std::istream& in) {
  static_assert(std::is_arithmetic_v<T> || std::is_enum_v<T>, "raw values only");
  T v{};
  if (!in.read(reinterpret_cast<char*>(&v), sizeof(T)))
    throw CheckpointError("unexpected end of data");
  return v;
}

void putBool(std::ostream& out, bool v);
bool getBool(std::istream& in);

void putCount(std::ostream& out, std::size_t n);
// Checked against kMaxCount and, in a stream that can tell (a restart file's
// payload), against the bytes left: n items of at least minBytesEach bytes
// each must fit in them, so that a crafted count allocates nothing the data
// cannot fill.
std::size_t getCount(std::istream& in, std::size_t minBytesEach = 1);

void putString(std::ostream& out, const std::string& s);
std::string getString(std::istream& in);

void putDoubles(std::ostream& out, const double* p, std::size_t n);
void getDoubles(std::istream& in, double* p, std::size_t n);

// Fixed-size Eigen objects (vectors, matrices): the coefficients only.
template <class M>
void putFixed(std::ostream& out, const Eigen::PlainObjectBase<M>& m) {
  static_assert(M::SizeAtCompileTime != Eigen::Dynamic, "fixed-size objects only");
  putDoubles(out, m.data(), static_cast<std::size_t>(m.size()));
}
template <class M>
void getFixed(std::istream& in, Eigen::PlainObjectBase<M>& m) {
  static_assert(M::SizeAtCompileTime != Eigen::Dynamic, "fixed-size objects only");
  getDoubles(in, m.data(), static_cast<std::size_t>(m.size()));
}

// Dynamic vectors: size, then the coefficients.
void putVector(std::ostream& out, const Eigen::VectorXd& v);
Eigen::VectorXd getVector(std::istream& in);

void putOptional(std::ostream& out, const std::optional<double>& v);
std::optional<double> getOptional(std::istream& in);

// A tag that opens a section; reading checks it, so a reader that lost its
// place fails at the next section instead of reading garbage.
void putTag(std::ostream& out, const char (&tag)[5]);
void expectTag(std::istream& in, const char (&tag)[5]);

}  // namespace checkpoint

}  // namespace c2d
