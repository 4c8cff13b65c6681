// The lines of a CSV log (src/io/line_reader.hpp): line ends, the byte-order mark, blank and
// comment lines, records joined across lines, positions and the bound on a line.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "dynpos/io/csv_reader.hpp"
#include "io_test_util.hpp"
#include "line_reader.hpp"

namespace dynpos::io {
namespace {

using detail::LinePosition;
using detail::LineReader;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using testing::input_error_message;
using ::testing::Pair;
using testing::TempDir;

// Every record of the file with the line it starts on.
std::vector<std::pair<std::string, std::size_t>> records(LineReader& reader) {
  std::vector<std::pair<std::string, std::size_t>> out;
  std::string record;
  std::size_t line = 0;
  while (reader.next(record, line)) out.emplace_back(record, line);
  return out;
}

std::vector<std::pair<std::string, std::size_t>> records_of(std::string_view text,
                                                            std::string comment_prefix = "#") {
  const TempDir dir;
  LineReader reader(dir.write("log.csv", text), std::move(comment_prefix));
  return records(reader);
}

TEST(LineReader, SplitsLfAndCrLfLineEnds) {
  EXPECT_THAT(records_of("t,x\n1,2\n"), ElementsAre(Pair("t,x", 1), Pair("1,2", 2)));
  EXPECT_THAT(records_of("t,x\r\n1,2\r\n3,4\n"),
              ElementsAre(Pair("t,x", 1), Pair("1,2", 2), Pair("3,4", 3)));
}

TEST(LineReader, ReadsALastLineWithoutLineEnd) {
  EXPECT_THAT(records_of("t,x\n1,2"), ElementsAre(Pair("t,x", 1), Pair("1,2", 2)));
  EXPECT_THAT(records_of("t,x\r\n1,2\r"), ElementsAre(Pair("t,x", 1), Pair("1,2", 2)));
}

TEST(LineReader, DropsTheByteOrderMarkOfTheFirstLineOnly) {
  EXPECT_THAT(records_of("\xEF\xBB\xBFt,x\n\xEF\xBB\xBF"
                         "1,2\n"),
              ElementsAre(Pair("t,x", 1), Pair("\xEF\xBB\xBF"
                                               "1,2",
                                               2)));
}

TEST(LineReader, SkipsBlankAndCommentLinesCountingThem) {
  EXPECT_THAT(records_of("# logger v2\n\nt,x\n   \n\t\r\n  # note\n1,2\n\n"),
              ElementsAre(Pair("t,x", 3), Pair("1,2", 7)));
  // No prefix: a '#' line is a record.
  EXPECT_THAT(records_of("#t,x\n1,2\n", ""), ElementsAre(Pair("#t,x", 1), Pair("1,2", 2)));
  // A longer prefix.
  EXPECT_THAT(records_of("// c\n/x\n", "//"), ElementsAre(Pair("/x", 2)));
}

TEST(LineReader, EmptyFileHasNoRecords) {
  EXPECT_TRUE(records_of("").empty());
  EXPECT_TRUE(records_of("\n\r\n\n").empty());
}

TEST(LineReader, RefusesLinesEndedByCrAlone) {
  const TempDir dir;
  LineReader reader(dir.write("mac.csv", "t,x\r1,2\r3,4\r"), "#");
  std::string record;
  std::size_t line = 0;
  const std::string message = input_error_message([&] { reader.next(record, line); });
  EXPECT_THAT(message, HasSubstr("mac.csv:1:4"));
  EXPECT_THAT(message, HasSubstr("a carriage return (CR) within the first line"));
}

TEST(LineReader, JoinsALineToAnOpenRecord) {
  const TempDir dir;
  LineReader reader(dir.write("q.csv", "t,note\n1,\"two\r\nlines\"\n2,x"), "#");
  std::string record;
  std::size_t line = 0;
  ASSERT_TRUE(reader.next(record, line));
  ASSERT_TRUE(reader.next(record, line));
  EXPECT_EQ(record, "1,\"two");
  EXPECT_EQ(line, 2u);
  ASSERT_TRUE(reader.continue_record(record));
  EXPECT_EQ(record, "1,\"two\nlines\"");
  EXPECT_EQ(reader.line(), 3u);
  ASSERT_TRUE(reader.next(record, line));
  EXPECT_EQ(record, "2,x");
  EXPECT_EQ(line, 4u);
  EXPECT_FALSE(reader.continue_record(record));
  EXPECT_FALSE(reader.next(record, line));
}

TEST(LineReader, PositionIsTheNextLineStartAndSeekGoesBack) {
  const TempDir dir;
  const std::string text = "\xEF\xBB\xBFt,x\r\n1,2\n\n3,4";
  LineReader reader(dir.write("p.csv", text), "#");
  std::string record;
  std::size_t line = 0;
  ASSERT_TRUE(reader.next(record, line));
  EXPECT_EQ(reader.position().offset, 8u);  // the BOM and CR LF counted
  EXPECT_EQ(reader.position().line, 1u);
  ASSERT_TRUE(reader.next(record, line));
  const LinePosition after_row = reader.position();
  EXPECT_EQ(after_row.offset, 12u);
  EXPECT_EQ(after_row.line, 2u);
  ASSERT_TRUE(reader.next(record, line));
  EXPECT_EQ(record, "3,4");
  EXPECT_EQ(line, 4u);
  EXPECT_EQ(reader.position().offset, text.size());
  EXPECT_FALSE(reader.next(record, line));

  reader.seek(after_row);
  ASSERT_TRUE(reader.next(record, line));
  EXPECT_EQ(record, "3,4");
  EXPECT_EQ(line, 4u);
  reader.seek({8, 1});
  ASSERT_TRUE(reader.next(record, line));
  EXPECT_EQ(record, "1,2");
  EXPECT_EQ(line, 2u);
}

TEST(LineReader, RefusesALineBeyondTheBound) {
  const TempDir dir;
  std::string text = "t,x\n1,2\n";
  text.append(kMaxCsvRecordBytes + 1, '7');
  text += "\n3,4\n";
  LineReader reader(dir.write("long.csv", text), "#");
  std::string record;
  std::size_t line = 0;
  ASSERT_TRUE(reader.next(record, line));
  ASSERT_TRUE(reader.next(record, line));
  const std::string message = input_error_message([&] { reader.next(record, line); });
  EXPECT_THAT(message, HasSubstr("long.csv:3"));
  EXPECT_THAT(message, HasSubstr("a line longer than 8 MiB"));
}

TEST(LineReader, AcceptsALineAtTheBound) {
  const TempDir dir;
  std::string text = "t\n";
  text.append(kMaxCsvRecordBytes, '7');  // a CR before the LF would count: one byte over
  text += "\n";
  LineReader reader(dir.write("edge.csv", text), "#");
  const auto all = records(reader);
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[1].first.size(), kMaxCsvRecordBytes);
  EXPECT_EQ(all[1].second, 2u);
  EXPECT_EQ(reader.position().offset, text.size());
}

TEST(LineReader, RefusesARecordJoinedBeyondTheBound) {
  const TempDir dir;
  std::string text = "t,x\n1,\"";
  text.append(kMaxCsvRecordBytes / 2, 'a');
  text += '\n';
  text.append(kMaxCsvRecordBytes / 2, 'b');
  text += "\"\n";
  LineReader reader(dir.write("open.csv", text), "#");
  std::string record;
  std::size_t line = 0;
  ASSERT_TRUE(reader.next(record, line));
  ASSERT_TRUE(reader.next(record, line));
  const std::string message = input_error_message([&] { reader.continue_record(record); });
  EXPECT_THAT(message, HasSubstr("open.csv:2"));
  EXPECT_THAT(message, HasSubstr("a record longer than 8 MiB"));
}

TEST(LineReader, NamesAFileThatCannotBeOpened) {
  const TempDir dir;
  const std::string message =
      input_error_message([&] { LineReader reader(dir / "absent.csv", "#"); });
  EXPECT_THAT(message, HasSubstr("absent.csv"));
  EXPECT_THAT(message, HasSubstr("cannot open the log"));
}

}  // namespace
}  // namespace dynpos::io
