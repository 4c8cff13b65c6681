// The lines of a live stream: cut at '\n' however the bytes arrive, tag blocks removed, bad
// ones counted (an error with strict), datagrams completed.

#include "dynpos/live/stream_lines.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "dynpos/core/error.hpp"

namespace dynpos::live {
namespace {

struct Collected {
  std::vector<std::string> lines;
  std::vector<bool> whole;
  LineSink sink() {
    return [this](std::string_view line, bool w) {
      lines.emplace_back(line);
      whole.push_back(w);
    };
  }
};

TEST(StreamLines, BytesInAnyPiecesGiveTheSameLines) {
  const std::string text = "time,x\r\n0,1\n0.1,2\r\n0.2,3\n";
  for (std::size_t piece = 1; piece <= text.size(); ++piece) {
    Collected c;
    StreamLines lines("test", false, c.sink());
    for (std::size_t at = 0; at < text.size(); at += piece) lines.add_bytes(text.substr(at, piece));
    lines.finish();
    ASSERT_EQ(c.lines, (std::vector<std::string>{"time,x\r\n", "0,1\n", "0.1,2\r\n", "0.2,3\n"}))
        << "pieces of " << piece;
    EXPECT_EQ(lines.counts().lines, 4u);
    EXPECT_EQ(lines.counts().bytes, text.size());
  }
}

TEST(StreamLines, TheRestAtTheEndIsPassedOnAsItIs) {
  Collected c;
  StreamLines lines("test", false, c.sink());
  lines.add_bytes("a\nb");
  lines.finish();
  EXPECT_EQ(c.lines, (std::vector<std::string>{"a\n", "b"}));
  EXPECT_EQ(c.whole, (std::vector<bool>{true, false}));
}

TEST(StreamLines, TagBlocksAreRemovedAndBadOnesCounted) {
  Collected c;
  StreamLines lines("udp x", false, c.sink());
  // "s:GP01" XORs to 0x5F (worked out outside the code).
  lines.add_bytes("\\s:GP01*5F\\$GPHDT,1.0,T*00\r\n\\s:GP01*58\\$GPHDT,2.0,T*00\r\n$GPHDT,3,T\r\n");
  EXPECT_EQ(c.lines, (std::vector<std::string>{"$GPHDT,1.0,T*00\r\n", "$GPHDT,3,T\r\n"}));
  EXPECT_EQ(lines.counts().tag_blocks, 1u);
  EXPECT_EQ(lines.counts().bad_tag_blocks, 1u);
}

TEST(StreamLines, StrictMakesABadTagBlockAnErrorNamingTheLine) {
  Collected c;
  StreamLines lines("udp 127.0.0.1:10110", true, c.sink());
  lines.add_bytes("$GPHDT,3,T\r\n");
  try {
    lines.add_bytes("\\s:GP01*58\\$GPHDT,2.0,T*00\r\n");
    FAIL() << "no error";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.where().file, "udp 127.0.0.1:10110");
    EXPECT_EQ(e.where().line, 2u);
    EXPECT_NE(std::string(e.what()).find("checksum"), std::string::npos) << e.what();
  }
}

TEST(StreamLines, DatagramsHoldWholeLines) {
  Collected c;
  StreamLines lines("udp x", false, c.sink());
  lines.add_datagram(std::string("UdPbC\0", 6) + "\\s:GP01*5F\\$GPHDT,1.0,T*00");
  lines.add_datagram("$GPHDT,2.0,T*00\r\n$GPHDT,3.0,T*00\r\n");
  lines.add_datagram(std::string("RaUdP\0", 6) + "binary data");
  EXPECT_EQ(c.lines, (std::vector<std::string>{"$GPHDT,1.0,T*00\r\n", "$GPHDT,2.0,T*00\r\n",
                                               "$GPHDT,3.0,T*00\r\n"}));
  EXPECT_EQ(lines.counts().other_datagrams, 1u);
}

}  // namespace
}  // namespace dynpos::live
