#pragma once
// Bounds-checked reading of little- and big-endian numbers from bytes (private to the module).

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

namespace dynpos::io::detail {

/// Bytes that do not hold what their format declares: the problem, and the byte offset (in
/// the bytes the reader was given) where it was found. The reader that knows the file turns
/// it into a core::InputError.
class ByteError : public std::runtime_error {
 public:
  ByteError(std::string problem, std::uint64_t offset)
      : std::runtime_error(std::move(problem)), offset(offset) {}
  std::uint64_t offset;
};

/// Little-endian reads from `bytes`, each checked against the bytes left.
class ByteCursor {
 public:
  explicit ByteCursor(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}

  std::size_t pos() const noexcept { return pos_; }
  std::size_t left() const noexcept { return bytes_.size() - pos_; }
  bool done() const noexcept { return pos_ == bytes_.size(); }

  /// Throws ByteError naming `what` unless n bytes are left.
  void need(std::uint64_t n, std::string_view what) const {
    if (n > left()) {
      throw ByteError(std::string(what) + " needs " + std::to_string(n) + " bytes, only " +
                          std::to_string(left()) + " are left",
                      pos_);
    }
  }
  template <class T>
  T number(std::string_view what) {
    need(sizeof(T), what);
    T value;
    std::memcpy(&value, bytes_.data() + pos_, sizeof(T));  // little-endian host (x86, ARM)
    pos_ += sizeof(T);
    return value;
  }
  std::uint8_t u8(std::string_view what) { return number<std::uint8_t>(what); }
  std::uint16_t u16(std::string_view what) { return number<std::uint16_t>(what); }
  std::uint32_t u32(std::string_view what) { return number<std::uint32_t>(what); }
  std::uint64_t u64(std::string_view what) { return number<std::uint64_t>(what); }
  /// n bytes.
  std::span<const std::uint8_t> bytes(std::uint64_t n, std::string_view what) {
    need(n, what);
    const auto out = bytes_.subspan(pos_, static_cast<std::size_t>(n));
    pos_ += static_cast<std::size_t>(n);
    return out;
  }
  /// A string with a uint32 length prefix.
  std::string_view string(std::string_view what) {
    const std::uint32_t n = u32(what);
    const auto b = bytes(n, what);
    return {reinterpret_cast<const char*>(b.data()), b.size()};
  }
  void skip(std::uint64_t n, std::string_view what) { bytes(n, what); }

 private:
  std::span<const std::uint8_t> bytes_;
  std::size_t pos_ = 0;
};

}  // namespace dynpos::io::detail
