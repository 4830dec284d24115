// Little-endian byte streams of the template file format (docs/model.md): the writer
// appends fields, the reader takes them with bounds checks and throws
// std::runtime_error naming the source, the field and the byte offset; FNV-1a is the
// file's checksum.
#pragma once

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace scatterer::detail {

// FNV-1a 64 over the bytes (the file's trailing checksum).
inline std::uint64_t fnv1a(const std::uint8_t* data, std::size_t size)
{
  std::uint64_t hash = 0xCBF29CE484222325ull;
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= data[i];
    hash *= 0x100000001B3ull;
  }
  return hash;
}

inline std::uint64_t load64(const std::uint8_t* p)
{
  std::uint64_t v = 0;
  for (int i = 0; i < 8; ++i) {
    v |= static_cast<std::uint64_t>(p[i]) << (8 * i);
  }
  return v;
}

class Writer {
public:
  std::vector<std::uint8_t> bytes;

  void u8(std::uint8_t v) { bytes.push_back(v); }
  void u32(std::uint32_t v)
  {
    for (int i = 0; i < 4; ++i) {
      bytes.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
    }
  }
  void u64(std::uint64_t v)
  {
    for (int i = 0; i < 8; ++i) {
      bytes.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
    }
  }
  void f32(float v)
  {
    std::uint32_t b;
    std::memcpy(&b, &v, 4);
    u32(b);
  }
  void f64(double v)
  {
    std::uint64_t b;
    std::memcpy(&b, &v, 8);
    u64(b);
  }
};

class Reader {
public:
  Reader(const std::uint8_t* data, std::size_t size, std::string source)
      : data_(data), size_(size), source_(std::move(source))
  {
  }

  [[noreturn]] void fail(const std::string& what) const { failAt(pos_, what); }
  // For a problem with an earlier byte than the next one: the offset of the field or
  // byte at fault.
  [[noreturn]] void failAt(std::size_t at, const std::string& what) const
  {
    throw std::runtime_error(source_ + ": " + what + " (at byte " + std::to_string(at) + ")");
  }
  std::size_t remaining() const { return size_ - pos_; }
  std::size_t position() const { return pos_; }

  const std::uint8_t* take(std::size_t n, const char* what)
  {
    if (n > remaining()) {
      fail(std::string("truncated: ") + what + " needs " + std::to_string(n) + " bytes, " +
           std::to_string(remaining()) + " left");
    }
    const std::uint8_t* p = data_ + pos_;
    pos_ += n;
    return p;
  }
  std::uint8_t u8(const char* what) { return *take(1, what); }
  std::uint32_t u32(const char* what)
  {
    const std::uint8_t* p = take(4, what);
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) {
      v |= static_cast<std::uint32_t>(p[i]) << (8 * i);
    }
    return v;
  }
  std::uint64_t u64(const char* what)
  {
    const std::uint8_t* p = take(8, what);
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) {
      v |= static_cast<std::uint64_t>(p[i]) << (8 * i);
    }
    return v;
  }
  float f32(const char* what)
  {
    const std::uint32_t b = u32(what);
    float v;
    std::memcpy(&v, &b, 4);
    return v;
  }
  double f64(const char* what)
  {
    const std::uint64_t b = u64(what);
    double v;
    std::memcpy(&v, &b, 8);
    return v;
  }
  // A count that is within its cap and whose records can fit in the remaining bytes.
  std::uint32_t count(const char* what, std::uint32_t cap, std::size_t minRecordBytes)
  {
    const std::uint32_t n = u32(what);
    if (n > cap) {
      fail(std::string("absurd ") + what + " " + std::to_string(n) + " (at most " +
           std::to_string(cap) + ")");
    }
    if (minRecordBytes > 0 && n > remaining() / minRecordBytes) {
      fail(std::string("truncated: ") + what + " " + std::to_string(n) + " does not fit in the " +
           std::to_string(remaining()) + " bytes left");
    }
    return n;
  }

private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
  std::string source_;
};

} // namespace scatterer::detail
