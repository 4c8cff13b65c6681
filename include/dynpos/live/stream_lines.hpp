#pragma once
/// \file
/// The lines of a live stream, as they arrive: bytes of a byte stream (TCP, a growing file) or
/// datagrams (UDP, each a whole number of lines), cut at '\n' with the line end kept; the
/// IEC 61162-450 header and tag blocks (tag_block.hpp) removed, so that what remains is what a
/// logger would have written, read by the analyses' own readers.

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>

namespace dynpos::live {

/// What was taken out of the stream.
struct StreamCounts {
  std::size_t bytes = 0;            ///< bytes received (datagrams' headers included)
  std::size_t datagrams = 0;        ///< datagrams received (UDP; 0 for a byte stream)
  std::size_t lines = 0;            ///< lines passed on
  std::size_t tag_blocks = 0;       ///< lines whose tag blocks were read and removed
  std::size_t bad_tag_blocks = 0;   ///< lines dropped: a tag block with a bad checksum or form
  std::size_t other_datagrams = 0;  ///< IEC 61162-450 datagrams of another type, dropped
  std::size_t unterminated_bytes =
      0;  ///< bytes passed on without a line end (a line over the bound)
};

/// Receives each line, line end included, and whether it is whole (false: the first part of a
/// line longer than StreamLines::kMaxLineBytes, or the rest of the stream at its end).
using LineSink = std::function<void(std::string_view line, bool whole)>;

/// Not thread-safe: one thread passes the stream to it (a live session's reader).
class StreamLines {
 public:
  /// A line longer than this [bytes] is passed on in parts as it comes (the readers bound it).
  static constexpr std::size_t kMaxLineBytes = std::size_t{1} << 20;

  /// `name` ("udp 127.0.0.1:10110", a file) names the stream in errors; `strict` makes a bad
  /// tag block a core::InputError naming the stream and the line.
  StreamLines(std::string name, bool strict, LineSink sink);

  /// Bytes of a byte stream.
  void add_bytes(std::string_view bytes);
  /// One datagram: its UdPbC header dropped, a last line without a line end completed by "\r\n".
  void add_datagram(std::string_view datagram);
  /// The end of the stream: a last line without a line end passed on as it is.
  void finish();

  const StreamCounts& counts() const noexcept { return counts_; }

 private:
  void emit(std::string_view line);

  std::string name_;
  bool strict_;
  LineSink sink_;
  std::string pending_;
  std::size_t line_number_ = 0;
  StreamCounts counts_;
};

}  // namespace dynpos::live
