#include "dynpos/live/tag_block.hpp"

#include <cstdint>

namespace dynpos::live {
namespace {

constexpr std::string_view kSentenceHeader{"UdPbC\0", 6};
constexpr std::size_t kHeaderBytes = 6;

int hex_value(char c) noexcept {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

}  // namespace

std::string_view strip_udpbc_header(std::string_view datagram) noexcept {
  if (datagram.starts_with(kSentenceHeader)) datagram.remove_prefix(kHeaderBytes);
  return datagram;
}

bool is_other_450_datagram(std::string_view datagram) noexcept {
  if (datagram.size() < kHeaderBytes || datagram[kHeaderBytes - 1] != '\0') return false;
  if (datagram.starts_with(kSentenceHeader)) return false;
  for (std::size_t i = 0; i + 1 < kHeaderBytes; ++i) {
    const char c = datagram[i];
    if (!((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'))) return false;
  }
  return true;
}

TaggedLine read_tag_blocks(std::string_view line) noexcept {
  TaggedLine out{line, TagBlockStatus::kNone};
  while (out.sentence.starts_with('\\')) {
    const std::size_t close = out.sentence.find('\\', 1);
    if (close == std::string_view::npos) {
      out.status = TagBlockStatus::kMalformed;
      return out;
    }
    const std::string_view block = out.sentence.substr(1, close - 1);
    out.sentence.remove_prefix(close + 1);
    const std::size_t star = block.rfind('*');
    if (star == std::string_view::npos) {  // no checksum: accepted, as a sentence without one
      out.status = TagBlockStatus::kValid;
      continue;
    }
    if (block.size() != star + 3 || hex_value(block[star + 1]) < 0 ||
        hex_value(block[star + 2]) < 0) {
      out.status = TagBlockStatus::kMalformed;
      return out;
    }
    std::uint8_t sum = 0;
    for (const char c : block.substr(0, star)) sum ^= static_cast<std::uint8_t>(c);
    const int given = hex_value(block[star + 1]) * 16 + hex_value(block[star + 2]);
    if (given != sum) {
      out.status = TagBlockStatus::kBadChecksum;
      return out;
    }
    out.status = TagBlockStatus::kValid;
  }
  return out;
}

}  // namespace dynpos::live
