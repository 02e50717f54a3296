#pragma once
// The binary form of a World snapshot (world/world_snapshot.h): little-endian fixed-width
// integers, doubles by their IEEE-754 bit pattern, so a snapshot reads back bit for bit on any
// machine (as Jolt's StateRecorder writes raw values, Jolt/Physics/StateRecorder.h). The reader
// checks every read against the bytes left and bounds every count by them, so a truncated or
// corrupted blob is a std::invalid_argument, never an overrun or a huge allocation.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "rbsim/math/types.h"

namespace rbsim {

class ByteWriter {
 public:
  void u8(std::uint8_t v) { bytes_.push_back(v); }
  void boolean(bool v) { u8(v ? 1 : 0); }
  void u32(std::uint32_t v) {
    for (int k = 0; k < 4; ++k) bytes_.push_back(static_cast<std::uint8_t>(v >> (8 * k)));
  }
  void u64(std::uint64_t v) {
    for (int k = 0; k < 8; ++k) bytes_.push_back(static_cast<std::uint8_t>(v >> (8 * k)));
  }
  void i64(std::int64_t v) { u64(static_cast<std::uint64_t>(v)); }
  void f64(double v) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    u64(bits);
  }
  void vec3(const Vec3& v) {
    for (int k = 0; k < 3; ++k) f64(v[k]);
  }
  void quat(const Quat& q) {  // x, y, z, w: Eigen's coefficient order
    for (int k = 0; k < 4; ++k) f64(q.coeffs()[k]);
  }
  void mat3(const Mat3& m) {
    for (int k = 0; k < 9; ++k) f64(m.data()[k]);
  }
  void text(const std::string& s) {
    u64(s.size());
    bytes_.insert(bytes_.end(), s.begin(), s.end());
  }
  void count(std::size_t n) { u64(n); }
  std::vector<std::uint8_t>& bytes() { return bytes_; }

 private:
  std::vector<std::uint8_t> bytes_;
};

class ByteReader {
 public:
  // `what` names the blob in every message (a file, "snapshot").
  ByteReader(const std::uint8_t* data, std::size_t size, std::string what) : data_(data), size_(size), what_(std::move(what)) {}

  std::size_t remaining() const { return size_ - at_; }
  std::size_t offset() const { return at_; }
  [[noreturn]] void fail(const std::string& problem) const {
    throw std::invalid_argument(what_ + ": at byte " + std::to_string(at_) + ": " + problem);
  }
  std::uint8_t u8() {
    need(1, "a byte");
    return data_[at_++];
  }
  bool boolean() {
    const std::uint8_t v = u8();
    if (v > 1) fail("expected a flag 0 or 1, found " + std::to_string(v));
    return v == 1;
  }
  std::uint32_t u32() {
    need(4, "a 32-bit integer");
    std::uint32_t v = 0;
    for (int k = 0; k < 4; ++k) v |= std::uint32_t{data_[at_++]} << (8 * k);
    return v;
  }
  std::uint64_t u64() {
    need(8, "a 64-bit integer");
    std::uint64_t v = 0;
    for (int k = 0; k < 8; ++k) v |= std::uint64_t{data_[at_++]} << (8 * k);
    return v;
  }
  std::int64_t i64() { return static_cast<std::int64_t>(u64()); }
  double f64() {
    const std::uint64_t bits = u64();
    double v = 0.0;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  }
  Vec3 vec3() {
    Vec3 v;
    for (int k = 0; k < 3; ++k) v[k] = f64();
    return v;
  }
  Quat quat() {
    Quat q;
    for (int k = 0; k < 4; ++k) q.coeffs()[k] = f64();
    return q;
  }
  Mat3 mat3() {
    Mat3 m;
    for (int k = 0; k < 9; ++k) m.data()[k] = f64();
    return m;
  }
  std::string text() {
    const std::size_t n = count(1, "characters of a text");
    std::string s(reinterpret_cast<const char*>(data_ + at_), n);
    at_ += n;
    return s;
  }
  // A count of items that take at least `minBytes` each in what follows: larger than the bytes
  // left can hold is a corrupted blob (bounding every allocation by the blob's size).
  std::size_t count(std::size_t minBytes, const char* items) {
    const std::uint64_t n = u64();
    if (minBytes > 0 && n > remaining() / minBytes) {
      fail(std::string("a count of ") + std::to_string(n) + " " + items + " where " + std::to_string(remaining()) +
           " bytes are left");
    }
    return static_cast<std::size_t>(n);
  }
  // An index below `bound` (a body, a plane, a slot).
  std::size_t index(std::size_t bound, const char* what) {
    const std::uint64_t v = u64();
    if (v >= bound) fail(std::string(what) + " " + std::to_string(v) + " out of range (expected < " + std::to_string(bound) + ")");
    return static_cast<std::size_t>(v);
  }

 private:
  void need(std::size_t n, const char* item) {
    if (remaining() < n) fail(std::string("truncated: expected ") + item + ", " + std::to_string(remaining()) + " bytes left");
  }

  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t at_ = 0;
  std::string what_;
};

}  // namespace rbsim
