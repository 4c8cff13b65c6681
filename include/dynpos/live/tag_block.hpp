#pragma once
/// \file
/// IEC 61162-450 framing of NMEA 0183 sentences on a network: the "UdPbC" header of a datagram
/// and the tag block before a sentence, `\s:GP0001,c:1700000000*5B\$GPGGA,…`. The tag block's
/// checksum is the XOR of the characters between the leading '\' and the '*', as a sentence's.

#include <cstddef>
#include <string_view>

namespace dynpos::live {

/// The datagram's payload: the bytes after a leading "UdPbC\0" header, or the whole datagram
/// when it has none (plain NMEA over UDP).
std::string_view strip_udpbc_header(std::string_view datagram) noexcept;

/// Whether a datagram carries another IEC 61162-450 type ("RaUdP\0": binary file transfer, …):
/// a six-byte header of letters ending in NUL that is not "UdPbC".
bool is_other_450_datagram(std::string_view datagram) noexcept;

/// How the tag blocks before a line's sentence were read.
enum class TagBlockStatus {
  kNone,         ///< the line has no tag block
  kValid,        ///< tag block(s) with a right checksum (or none given), removed
  kBadChecksum,  ///< a tag block whose checksum does not match its text
  kMalformed,    ///< a '\' without its closing '\', or a checksum that is not two hex digits
};

/// A line with its tag blocks read.
struct TaggedLine {
  std::string_view sentence;  ///< the line after its tag blocks (the whole line without one)
  TagBlockStatus status = TagBlockStatus::kNone;
};

/// Reads the tag blocks at the start of `line` (one after the other, as a group's sentences
/// carry them) and checks each one's checksum. On kBadChecksum and kMalformed `sentence` is
/// the rest after what could be read, for a caller that counts the line and goes on.
TaggedLine read_tag_blocks(std::string_view line) noexcept;

}  // namespace dynpos::live
