// The CSV reader parses a regular file in blocks on several threads (src/io/csv_blocks.hpp) and
// reads a pipe row by row. Both must give the same log, the same notes and the same errors, bit
// for bit: here every case is a file of several 1 MiB blocks, read as a file with 1, 2 and 3
// threads and through a FIFO (the row-by-row reference), with a defect placed mid-file.

#include <sys/stat.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstring>
#include <fstream>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "csv_blocks.hpp"
#include "dynpos/io/csv_reader.hpp"
#include "io_test_util.hpp"

namespace dynpos::io {
namespace {

using testing::TempDir;

constexpr std::size_t kRows = 400'000;  // about 14 MB: thirteen blocks and a part

// Row k of a clean log: time, a command, a response and a spare column, 100 Hz.
std::string row(std::size_t k) {
  return fmt::format("{:.2f},{:.3f},{:.5f},{}\n", 0.01 * static_cast<double>(k),
                     static_cast<double>((k / 1000) % 7), std::sin(1e-3 * static_cast<double>(k)),
                     k % 13);
}

// The log's text, `edit` changing row k's line (return "" to keep it, or the replacement).
std::string log_text(const std::function<std::string(std::size_t)>& edit = {}) {
  std::string text = "# logger v1\ntime [s],cmd [1],resp [m],spare\n";
  text.reserve(kRows * 40);
  for (std::size_t k = 0; k < kRows; ++k) {
    const std::string changed = edit ? edit(k) : std::string();
    text += changed.empty() ? row(k) : changed;
  }
  return text;
}

ColumnMap map_of(TimeOrder order = TimeOrder::kError) {
  ColumnMap map;
  map.set_column("time", "time");
  map.set_column("input", "cmd");
  map.set_column("output", "resp");
  map.time().order = order;
  return map;
}

// A read's outcome: the log and notes, or the error text with the file name taken out.
struct Outcome {
  std::optional<CsvLog> log;
  std::string error;
};

Outcome read(const std::filesystem::path& path, const ColumnMap& map, CsvReadOptions options) {
  Outcome out;
  try {
    out.log = read_csv_log(path, map, options);
  } catch (const core::InputError& e) {
    out.error = e.what();
    for (std::size_t at; (at = out.error.find(path.string())) != std::string::npos;) {
      out.error.replace(at, path.string().size(), "LOG");
    }
  }
  return out;
}

// The same text through a FIFO: read row by row.
Outcome read_through_pipe(const TempDir& dir, const std::string& text, const ColumnMap& map,
                          const CsvReadOptions& options) {
  const auto fifo = dir / "pipe.csv";
  std::filesystem::remove(fifo);
  EXPECT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // A reader that stops early (an error, the end of a window) breaks the pipe: the writer's
  // write then fails with EPIPE instead of raising SIGPIPE.
  std::signal(SIGPIPE, SIG_IGN);
  std::thread writer([&] {
    std::ofstream out(fifo, std::ios::binary);
    out << text;
  });
  Outcome out = read(fifo, map, options);
  writer.join();
  return out;
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

void expect_same(const Outcome& reference, const Outcome& got, const std::string& how) {
  ASSERT_EQ(reference.error, got.error) << how;
  ASSERT_EQ(reference.log.has_value(), got.log.has_value()) << how;
  if (!reference.log) return;
  const core::Log& a = reference.log->log;
  const core::Log& b = got.log->log;
  EXPECT_TRUE(same_bits(a.time(), b.time())) << how;
  ASSERT_EQ(a.channel_names(), b.channel_names()) << how;
  for (const std::string& name : a.channel_names()) {
    EXPECT_TRUE(same_bits(a.values(name), b.values(name))) << how << ": " << name;
  }
  EXPECT_EQ(reference.log->time.skipped.by_kind(), got.log->time.skipped.by_kind()) << how;
  EXPECT_EQ(reference.log->time.notes, got.log->time.notes) << how;
}

// Reads `text` as a file with 1, 2 and 3 threads and through a pipe; all four must agree.
Outcome check_all_ways(const std::string& text, const ColumnMap& map, CsvReadOptions options = {}) {
  TempDir dir;
  const auto file = dir.write("log.csv", text);
  const Outcome reference = read_through_pipe(dir, text, map, options);
  for (const unsigned jobs : {1u, 2u, 3u}) {
    options.jobs = jobs;
    expect_same(reference, read(file, map, options), fmt::format("{} thread(s)", jobs));
  }
  return reference;
}

TEST(CsvBlocks, ACleanLogReadsTheSameAsRowByRow) {
  const Outcome r = check_all_ways(log_text(), map_of());
  ASSERT_TRUE(r.log);
  EXPECT_EQ(r.log->log.size(), kRows);
  const double logged = std::stod(fmt::format("{:.5f}", std::sin(123.456)));
  EXPECT_EQ(r.log->log.values("output")[123'456], logged);
}

TEST(CsvBlocks, ABadCellMidFileIsTheSameErrorOnTheSameLine) {
  const Outcome r =
      check_all_ways(log_text([](std::size_t k) {
                       return k == 250'000 ? std::string("2500.00,1.000,oops,3\n") : "";
                     }),
                     map_of());
  // Line: the comment, the header, then row k on line k + 3.
  EXPECT_THAT(r.error, ::testing::HasSubstr("LOG:250003:3"));
  EXPECT_THAT(r.error, ::testing::HasSubstr("'oops' is not a number"));
}

TEST(CsvBlocks, ARowBackInTimeIsDroppedAndCountedAsRowByRow) {
  const auto edit = [](std::size_t k) {
    return k == 300'000 ? std::string("2000.00,1.000,0.5,3\n") : std::string();
  };
  const Outcome r = check_all_ways(log_text(edit), map_of(TimeOrder::kDropNonIncreasing));
  ASSERT_TRUE(r.log);
  EXPECT_EQ(r.log->log.size(), kRows - 1);
  EXPECT_EQ(r.log->time.skipped.total(), 1u);
  const Outcome strict = check_all_ways(log_text(edit), map_of());
  EXPECT_THAT(strict.error, ::testing::HasSubstr("LOG:300003"));
}

TEST(CsvBlocks, QuotesBlankAndCommentLinesCrlfAndMissingCells) {
  const Outcome r =
      check_all_ways(log_text([](std::size_t k) -> std::string {
                       if (k == 100'000) return "\n# a note\n" + row(k);
                       if (k == 150'000) return "1500.00,\"2.000\",0.1,\"a,b\"\n";
                       if (k == 151'000) return "1510.00,\"multi\nline\",0.1,1\n";
                       if (k % 1000 == 7)
                         return fmt::format("{:.2f},,,1\r\n", 0.01 * static_cast<double>(k));
                       return "";
                     }),
                     map_of());
  // The quoted multi-line cell is text in a number column: the same error both ways.
  EXPECT_THAT(r.error, ::testing::HasSubstr("LOG:151005:2"));  // two extra lines above
  const Outcome ok =
      check_all_ways(log_text([](std::size_t k) -> std::string {
                       if (k == 100'000) return "\n# a note\n" + row(k);
                       if (k == 150'000) return "1500.00,\"2.000\",0.1,\"a,b\"\n";
                       if (k % 1000 == 7)
                         return fmt::format("{:.2f},,,1\r\n", 0.01 * static_cast<double>(k));
                       return "";
                     }),
                     map_of());
  ASSERT_TRUE(ok.log);
  EXPECT_EQ(ok.log->log.size(), kRows);
  EXPECT_TRUE(std::isnan(ok.log->log.values("input")[1007]));
  EXPECT_EQ(ok.log->log.values("input")[150'000], 2.0);
}

TEST(CsvBlocks, AWindowAcrossBlocksAndAnUnterminatedLastLine) {
  CsvReadOptions window;
  window.t_from_s = 1234.5;
  window.t_to_s = 2345.67;
  const Outcome r = check_all_ways(log_text(), map_of(), window);
  ASSERT_TRUE(r.log);
  EXPECT_EQ(r.log->log.time().front(), 1234.5);
  EXPECT_EQ(r.log->log.time().back(), 2345.67);
  std::string text = log_text();
  text.pop_back();  // no newline after the last row
  check_all_ways(text, map_of());
  text.resize(text.size() - 6);  // a row cut short by the logger
  const Outcome cut = check_all_ways(text, map_of());
  EXPECT_THAT(cut.error, ::testing::HasSubstr(fmt::format("LOG:{}", kRows + 2)));
}

// A missing token that is itself a number ("-999") is missing, in a block as row by row; cells
// with spaces, exponents or a '+' are read by the full cell parser, as row by row.
TEST(CsvBlocks, ANumericMissingTokenAndCellsThatAreNotPlainDecimals) {
  ColumnMap map = map_of();
  map.format().missing_tokens = {"-999"};
  const Outcome r = check_all_ways(log_text([](std::size_t k) -> std::string {
                                     const double t = 0.01 * static_cast<double>(k);
                                     if (k % 977 == 5)
                                       return fmt::format("{:.2f},-999,-999,1\n", t);
                                     if (k % 977 == 6)
                                       return fmt::format("{:.2f}, 2.5 ,1e-3,1\n", t);
                                     if (k % 977 == 7) return fmt::format("{:.2f},+3,-0,1\n", t);
                                     return "";
                                   }),
                                   map);
  ASSERT_TRUE(r.log);
  const core::Log& log = r.log->log;
  EXPECT_TRUE(std::isnan(log.values("input")[5]));
  EXPECT_TRUE(std::isnan(log.values("output")[977 + 5]));
  EXPECT_EQ(log.values("input")[6], 2.5);
  EXPECT_EQ(log.values("output")[6], 1e-3);
  EXPECT_EQ(log.values("input")[7], 3.0);
  EXPECT_TRUE(std::signbit(log.values("output")[7]));
  ColumnMap plain = map_of();  // without the token, -999 is a number
  const Outcome n =
      check_all_ways(log_text([](std::size_t k) -> std::string {
                       return k == 5 ? std::string("0.05,-999,0.5,1\n") : std::string();
                     }),
                     plain);
  ASSERT_TRUE(n.log);
  EXPECT_EQ(n.log->log.values("input")[5], -999.0);
}

// Rows that are not the common case, sprinkled among plain ones at random: CRLF and CR CR LF
// ends, blank and comment lines, leading spaces, missing and padded cells, numbers that are not
// plain decimals, a CR inside a cell; then, in some logs, one row that stops the reading (a field
// too many or too few, text in a number column). A row that is all plain decimals is read as its
// end is looked for; every other line must be read as row by row, with the last mapped field
// inside the line and at its end, and an unmapped field between mapped ones.
TEST(CsvBlocks, OddLinesAmongPlainRowsReadAsRowByRow) {
  const auto line = [](std::size_t k, int kind) -> std::string {
    const std::string t = fmt::format("{:.2f}", 0.01 * static_cast<double>(k));
    switch (kind) {
      case 0:
        return fmt::format("{},1.5,0.25,7\r\n", t);
      case 1:
        return fmt::format("{},1.5,0.25,7\r\r\n", t);
      case 2:
        return "\n" + row(k);
      case 3:
        return "# note\n" + row(k);
      case 4:
        return "  " + row(k);
      case 5:
        return fmt::format("{},,0.25,7\n", t);
      case 6:
        return fmt::format("{}, 1.5 ,0.25,7\n", t);
      case 7:
        return fmt::format("{},1e-3,+0.25,7\n", t);
      case 8:
        return fmt::format("{},1.,.5,7\n", t);
      case 9:
        return fmt::format("{},1.5\r,0.25,7\n", t);
      case 10:
        return fmt::format("{},1.5,0.25,\n", t);
      case 11:
        return fmt::format("{},1.5,0.25,7\r8\n", t);  // text, if the last field is mapped
      case 12:
        return fmt::format("{},1.5,0.25\r\n", t);  // a field too few
      default:
        return fmt::format("{},1.5,0.25,7,9\n", t);  // a field too many
    }
  };
  ColumnMap last_mapped = map_of();  // the last field parsed too
  last_mapped.set_column("trigger", "spare");
  ColumnMap gap;  // an unmapped field between the time and the output
  gap.set_column("time", "time");
  gap.set_column("output", "resp");
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    for (const ColumnMap* map : {&last_mapped, &gap}) {
      SCOPED_TRACE(fmt::format("seed {}, {}", seed, map == &gap ? "gap" : "last field mapped"));
      std::mt19937_64 engine(seed);
      std::bernoulli_distribution is_odd(seed % 2 == 1 ? 2e-4 : 3e-3);
      std::uniform_int_distribution<int> benign(0, map == &gap ? 11 : 10);
      const std::size_t stop_at =  // a row that stops the reading, in the second half
          seed >= 3 ? std::uniform_int_distribution<std::size_t>(200'000, 380'000)(engine) : kRows;
      const std::string text = log_text([&](std::size_t k) {
        if (k == stop_at) return line(k, seed == 3 ? 13 : 12);
        return k > 100 && is_odd(engine) ? line(k, benign(engine)) : std::string();
      });
      const Outcome r = check_all_ways(text, *map);
      EXPECT_EQ(r.log.has_value(), stop_at == kRows) << r.error;
      if (r.log) {
        EXPECT_EQ(r.log->log.size(), kRows);
      }
    }
  }
}

// A comment prefix that looks like the start of a number: the rows whose time begins with it
// are comments, in a block as row by row.
TEST(CsvBlocks, ACommentPrefixThatLooksLikeANumber) {
  ColumnMap map = map_of();
  map.format().comment_prefix = "9";
  std::string text = log_text();
  text.front() = '9';  // the first line, "# logger v1", stays a comment
  const Outcome r = check_all_ways(text, map);
  ASSERT_TRUE(r.log);
  const auto& t = r.log->log.time();
  EXPECT_EQ(std::count_if(t.begin(), t.end(),
                          [](double x) { return fmt::format("{:.2f}", x).front() == '9'; }),
            0);
  EXPECT_LT(t.size(), kRows);
}

// Each row of a clean block knows its line, with blank and comment lines between rows, after a
// block's last row and at a block's start: the line a row's time is found on in the text.
TEST(CsvBlocks, EachRowOfABlockKnowsItsLine) {
  TempDir dir;
  const std::string text = log_text([](std::size_t k) -> std::string {
    if (k % 977 == 5) return "# note\n\n" + row(k);
    if (k % 1500 == 9) return row(k) + "\n";
    return "";
  });
  const auto file = dir.write("log.csv", text);
  std::vector<std::size_t> line_start = {0};  // byte offset of each line (0-based lines)
  for (std::size_t i = 0; i + 1 < text.size(); ++i) {
    if (text[i] == '\n') line_start.push_back(i + 1);
  }
  detail::BlockLayout layout;
  layout.field_count = 4;
  layout.comment_prefix = "#";
  layout.time.field = 0;
  layout.channels.push_back({2, {}, 1.0});
  const std::uint64_t data_start = line_start[2];  // after the comment and the header
  for (const unsigned jobs : {1u, 2u}) {
    detail::BlockReader reader(file, layout, jobs);
    std::size_t blocks = 0, checked = 0;
    reader.stream(data_start, [&](const detail::Block& block) {
      EXPECT_TRUE(block.clean);
      const auto first = static_cast<std::size_t>(
          std::lower_bound(line_start.begin(), line_start.end(), block.begin) - line_start.begin());
      for (std::size_t i = 0; i < block.time_s.size(); ++i) {
        const std::size_t line = first + block.line_of_row(i);
        const std::size_t end = text.find(',', line_start[line]);
        EXPECT_EQ(std::stod(text.substr(line_start[line], end - line_start[line])), block.time_s[i])
            << "block " << blocks << " row " << i;
        ++checked;
      }
      ++blocks;
      return true;
    });
    EXPECT_GE(blocks, 10u);
    EXPECT_EQ(checked, kRows);
  }
}

// A logger that cuts its file while it is read (a rotation by copy and truncate): an error
// naming the file, never a reader waiting for bytes that will not come.
TEST(CsvBlocks, AFileThatShrinksWhileReadIsAnError) {
  TempDir dir;
  const auto file = dir.write("log.csv", log_text());
  detail::BlockLayout layout;
  layout.field_count = 4;
  layout.time.field = 0;
  layout.channels.push_back({2, {}, 1.0});
  const std::uint64_t data_start = log_text().find('\n', 12) + 1;  // after the header line
  for (const unsigned jobs : {1u, 2u}) {
    detail::BlockReader reader(file, layout, jobs);
    std::filesystem::resize_file(file, std::filesystem::file_size(file) / 2);
    std::size_t rows = 0;
    try {
      reader.stream(data_start, [&](const detail::Block& block) {
        rows += block.time_s.size();
        return true;
      });
      ADD_FAILURE() << "no error, " << rows << " rows";
    } catch (const core::InputError& e) {
      EXPECT_THAT(e.what(), ::testing::HasSubstr("the file shrank while it was read")) << jobs;
      EXPECT_THAT(e.what(), ::testing::HasSubstr(file.string())) << jobs;
    }
    std::filesystem::resize_file(file, 0);
    dir.write("log.csv", log_text());
  }
}

}  // namespace
}  // namespace dynpos::io
