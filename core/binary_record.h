// BinaryRecord: a flat record of numbers, matrices and strings, written and read back
// bit for bit, with a checksum. It carries what a run must keep to be resumed exactly:
// a method's warm start (OneStepMethod::saveWarmStart), the state of a relaxation
// (Relaxation::save) and an app's checkpoint (docs/reference/command-lines-and-files.md,
// "Checkpoints"). Numbers are stored as their bytes, never as text, so that a resumed run continues
// from the same doubles; shapes and tags are checked on reading, and a record that ends early,
// has a wrong tag or a wrong checksum throws CorruptRecord instead of yielding numbers.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>

namespace ddb {

/// A record that cannot be read back: truncated, altered, or not of the expected layout.
class CorruptRecord : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// FNV-1a's offset basis: the hash of no bytes.
constexpr std::uint64_t kFnv1a64Basis = 0xcbf29ce484222325ULL;

/// The 64-bit FNV-1a hash of `bytes` (Fowler, Noll, Vo): a checksum against truncation and
/// corruption, not against tampering. It is a stream hash: the hash of a + b is
/// fnv1a64(b, fnv1a64(a)), so that a file that grows can keep its hash as it is written.
inline std::uint64_t fnv1a64(std::string_view bytes, std::uint64_t hash = kFnv1a64Basis) {
  for (const char c : bytes) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

class BinaryRecordWriter {
 public:
  /// A tag names the part that follows, so that a reader of another layout fails at once.
  void tag(std::string_view name) { put(std::string(name)); }
  template <class T, std::enable_if_t<std::is_arithmetic_v<T>, int> = 0>
  void put(T value) {
    append(&value, sizeof(T));
  }
  void put(const std::string& text) {
    put(static_cast<std::uint64_t>(text.size()));
    append(text.data(), text.size());
  }
  /// A dense matrix or vector: rows, columns, then the coefficients in storage order.
  template <class Derived>
  void put(const Eigen::PlainObjectBase<Derived>& m) {
    put(static_cast<std::int64_t>(m.rows()));
    put(static_cast<std::int64_t>(m.cols()));
    append(m.data(), sizeof(typename Derived::Scalar) * static_cast<std::size_t>(m.size()));
  }

  const std::string& bytes() const { return bytes_; }
  /// The bytes followed by their checksum: what a file holds.
  std::string sealed() const {
    std::string out = bytes_;
    const std::uint64_t sum = fnv1a64(bytes_);
    out.append(reinterpret_cast<const char*>(&sum), sizeof(sum));
    return out;
  }

 private:
  void append(const void* data, std::size_t size) {
    bytes_.append(static_cast<const char*>(data), size);
  }
  std::string bytes_;
};

class BinaryRecordReader {
 public:
  /// Reads `bytes` as written by BinaryRecordWriter::bytes().
  explicit BinaryRecordReader(std::string bytes) : bytes_(std::move(bytes)) {}
  BinaryRecordReader(const BinaryRecordReader&) = default;
  BinaryRecordReader(BinaryRecordReader&&) = default;
  BinaryRecordReader& operator=(const BinaryRecordReader&) = default;
  BinaryRecordReader& operator=(BinaryRecordReader&&) = default;
  virtual ~BinaryRecordReader() = default;
  /// Reads a sealed record: checks and strips the checksum.
  static BinaryRecordReader unseal(std::string sealed) {
    std::uint64_t sum = 0;
    if (sealed.size() < sizeof(sum)) throw CorruptRecord("shorter than its checksum");
    std::memcpy(&sum, sealed.data() + sealed.size() - sizeof(sum), sizeof(sum));
    sealed.resize(sealed.size() - sizeof(sum));
    if (fnv1a64(sealed) != sum) throw CorruptRecord("checksum mismatch");
    return BinaryRecordReader(std::move(sealed));
  }

  void expectTag(std::string_view name) {
    const std::string found = get<std::string>();
    if (found != name) {
      throw CorruptRecord("expected part '" + std::string(name) + "', found '" + found + "'");
    }
  }
  template <class T>
  T get() {
    if constexpr (std::is_same_v<T, std::string>) {
      const auto size = get<std::uint64_t>();
      require(size);
      std::string text(size, '\0');
      take(text.data(), size);
      return text;
    } else {
      static_assert(std::is_arithmetic_v<T>, "get<T>: a number or a string");
      T value;
      take(&value, sizeof(T));
      return value;
    }
  }
  template <class T,
            std::enable_if_t<std::is_arithmetic_v<T> || std::is_same_v<T, std::string>, int> = 0>
  void get(T& value) {
    value = get<T>();
  }
  /// Reads a matrix into m, resizing it; a fixed size that does not match throws.
  template <class Derived>
  void get(Eigen::PlainObjectBase<Derived>& m) {
    const auto rows = get<std::int64_t>(), cols = get<std::int64_t>();
    constexpr auto kRows = Derived::RowsAtCompileTime, kCols = Derived::ColsAtCompileTime;
    if (rows < 0 || cols < 0 || (kRows != Eigen::Dynamic && rows != kRows) ||
        (kCols != Eigen::Dynamic && cols != kCols)) {
      throw CorruptRecord("a matrix of " + std::to_string(rows) + " x " + std::to_string(cols) +
                          " where the layout has another size");
    }
    // The size is checked against what is left before it is multiplied out, so that a
    // corrupt shape can neither overflow the product nor allocate beyond the record.
    constexpr auto kScalar = sizeof(typename Derived::Scalar);
    const auto r = static_cast<std::uint64_t>(rows), c = static_cast<std::uint64_t>(cols);
    if (r != 0 && c > std::numeric_limits<std::uint64_t>::max() / kScalar / r) {
      throw CorruptRecord("a matrix of " + std::to_string(rows) + " x " + std::to_string(cols) +
                          " larger than any record");
    }
    const auto bytes = static_cast<std::size_t>(kScalar * r * c);
    require(bytes);
    m.resize(rows, cols);
    take(m.data(), bytes);
  }
  /// Whether every byte was read.
  virtual bool atEnd() const { return at_ == bytes_.size(); }
  void expectEnd() const {
    if (!atEnd()) throw CorruptRecord("unexpected bytes after the record's end");
  }

 protected:
  // Where the bytes come from: this reader's own. A reader of a record that one process of
  // several holds (distributed/rank_zero_record_reader.h) overrides them and atEnd, so that the
  // layouts' readers (get, expectTag) serve it unchanged.
  /// Fails unless `size` more bytes are there to read.
  virtual void require(std::size_t size) const {
    if (!holds(size)) throw CorruptRecord("ends early");
  }
  /// Copies the next `size` bytes into `out`.
  virtual void take(void* out, std::size_t size) {
    require(size);
    takeHere(out, size);
  }
  bool holds(std::size_t size) const { return size <= bytes_.size() - at_; }
  /// The next `size` bytes of this reader's own, which the caller checked with holds().
  void takeHere(void* out, std::size_t size) {
    std::memcpy(out, bytes_.data() + at_, size);
    at_ += size;
  }

 private:
  std::string bytes_;
  std::size_t at_ = 0;
};

}  // namespace ddb
