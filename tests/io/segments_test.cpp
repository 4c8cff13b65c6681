#include "dynpos/io/segments.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "../source_dir.hpp"
#include "dynpos/core/error.hpp"
#include "io_test_util.hpp"

namespace dynpos::io {
namespace {

using ::testing::HasSubstr;
using testing::TempDir;

// The message of the InputError that read_segments throws for `text`.
std::string error_for(const std::string& text) {
  const TempDir dir;
  const auto path = dir.write("segments.csv", text);
  try {
    read_segments(path);
  } catch (const core::InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected a core::InputError for:\n" << text;
  return {};
}

TEST(Segments, HeaderCommentsAndOrder) {
  const TempDir dir;
  const auto path = dir.write("segments.csv",
                              "# bridge log\n"
                              "name, start, end\n"
                              "\n"
                              "turn port, 500, 800  # late\n"
                              "zigzag 10/10,100.5,400\n");
  const std::vector<Segment> s = read_segments(path);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].name, "zigzag 10/10");  // sorted by start
  EXPECT_EQ(s[0].start_s, 100.5);
  EXPECT_EQ(s[0].end_s, 400.0);
  EXPECT_EQ(s[0].line, 5u);
  EXPECT_EQ(s[1].name, "turn port");
  // Without a header the first row is a segment.
  EXPECT_EQ(read_segments(dir.write("bare.csv", "a,0,1\n")).size(), 1u);
}

TEST(Segments, TheFixtureReads) {
  const auto s =
      read_segments(std::filesystem::path(DYNPOS_SOURCE_DIR) / "tests/data/step_segments.csv");
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[1].name, "turn stb");
}

TEST(Segments, BadRowsNameFileLineAndColumn) {
  EXPECT_THAT(error_for("name,start,end\na,1,2\nb,3\n"), HasSubstr("segments.csv:3:3"));
  EXPECT_THAT(error_for("name,start,end\na,1,2\nb,3\n"), HasSubstr("2 field(s) instead of 3"));
  EXPECT_THAT(error_for("a,1,2\nb,3,4,5\n"), HasSubstr("segments.csv:2:4"));
  EXPECT_THAT(error_for("a,1,2\n,3,4\n"), HasSubstr("segments.csv:2:1: empty segment name"));
  EXPECT_THAT(error_for("a,1,2\nb,3,four\n"), HasSubstr("segments.csv:2:3: 'four' is not"));
  EXPECT_THAT(error_for("a,1,2\nb,inf,4\n"), HasSubstr("segments.csv:2:2"));
  EXPECT_THAT(error_for("a,5,2\n"), HasSubstr("segments.csv:1:3: the segment ends before"));
  EXPECT_THAT(error_for("a,0,10\nb,5,20\n"),
              HasSubstr("segments.csv:2:2: segment 'b' overlaps 'a'"));
  EXPECT_THAT(error_for("# nothing\nname,start,end\n"), HasSubstr("no segment in the file"));
}

}  // namespace
}  // namespace dynpos::io
