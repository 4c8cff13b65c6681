// IEC 61162-450 framing: the UdPbC header and tag blocks with their checksums.

#include "dynpos/live/tag_block.hpp"

#include <gtest/gtest.h>

#include <string>

namespace dynpos::live {
namespace {

// The checksum of a tag block's text, as two upper-case hex digits (computed here from the
// definition, independently of the parser).
std::string checksum(const std::string& text) {
  unsigned sum = 0;
  for (const char c : text) sum ^= static_cast<unsigned char>(c);
  const char* hex = "0123456789ABCDEF";
  return {hex[sum >> 4], hex[sum & 15]};
}

std::string tagged(const std::string& block, const std::string& sentence) {
  return "\\" + block + "*" + checksum(block) + "\\" + sentence;
}

TEST(TagBlock, AValidBlockIsRemoved) {
  const std::string sentence = "$GPHDT,123.4,T*00";
  const std::string line = tagged("s:GP0001,c:1700000000", sentence);
  const TaggedLine t = read_tag_blocks(line);  // views into `line`
  EXPECT_EQ(t.status, TagBlockStatus::kValid);
  EXPECT_EQ(t.sentence, sentence);
}

TEST(TagBlock, AChecksumWorkedOutBeforehand) {
  // The characters of "s:r3669961,c:1120959341" XOR to 0x7B (worked out outside the code).
  const TaggedLine t = read_tag_blocks("\\s:r3669961,c:1120959341*7B\\!AIVDM,1,1,,A,x,0*00");
  EXPECT_EQ(t.status, TagBlockStatus::kValid);
  EXPECT_EQ(t.sentence, "!AIVDM,1,1,,A,x,0*00");
}

TEST(TagBlock, ABadChecksumIsReported) {
  std::string line = tagged("s:GP0001,c:1700000000", "$GPHDT,1,T");
  line[3] = 'Q';  // one character changed after the checksum was made
  EXPECT_EQ(read_tag_blocks(line).status, TagBlockStatus::kBadChecksum);
}

TEST(TagBlock, GroupedBlocksAreAllChecked) {
  const std::string two = tagged("g:1-2-73", "") + tagged("s:GP01", "$GPHDT,2,T");
  const TaggedLine t = read_tag_blocks(two);
  EXPECT_EQ(t.status, TagBlockStatus::kValid);
  EXPECT_EQ(t.sentence, "$GPHDT,2,T");
  std::string bad = two;
  bad[bad.find("s:") + 2] = 'X';
  EXPECT_EQ(read_tag_blocks(bad).status, TagBlockStatus::kBadChecksum);
}

TEST(TagBlock, MalformedAndAbsent) {
  EXPECT_EQ(read_tag_blocks("\\s:GP01*5B$GPHDT").status, TagBlockStatus::kMalformed);
  EXPECT_EQ(read_tag_blocks("\\s:GP01*5\\$GPHDT").status, TagBlockStatus::kMalformed);
  EXPECT_EQ(read_tag_blocks("\\s:GP01\\$GPHDT").status, TagBlockStatus::kValid);
  const TaggedLine none = read_tag_blocks("$GPHDT,1,T");
  EXPECT_EQ(none.status, TagBlockStatus::kNone);
  EXPECT_EQ(none.sentence, "$GPHDT,1,T");
}

TEST(TagBlock, TheDatagramHeader) {
  const std::string payload = "\\s:GP01*00\\$GPHDT,1,T\r\n";
  EXPECT_EQ(strip_udpbc_header(std::string("UdPbC\0", 6) + payload), payload);
  EXPECT_EQ(strip_udpbc_header(payload), payload);
  EXPECT_TRUE(is_other_450_datagram(std::string("RaUdP\0", 6) + "binary"));
  EXPECT_FALSE(is_other_450_datagram(std::string("UdPbC\0", 6) + payload));
  EXPECT_FALSE(is_other_450_datagram("$GPHDT,1,T"));
}

}  // namespace
}  // namespace dynpos::live
