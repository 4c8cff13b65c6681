// The line dynpos live prints at a session's end.

#include <gtest/gtest.h>

#include "dynpos/live/session.hpp"

namespace dynpos::live {
namespace {

TEST(LiveSummaryText, EveryCountInOneLine) {
  LiveSummary s;
  s.counts.bytes = 123456;
  s.counts.datagrams = 40;
  s.counts.lines = 900;
  s.counts.tag_blocks = 800;
  s.counts.bad_tag_blocks = 2;
  s.counts.other_datagrams = 1;
  s.queue_peak_lines = 77;
  s.queue_peak_bytes = 2'345'678;
  s.runs = 12;
  s.run_cpu_s = 0.12345;
  s.lines_written = 11;
  EXPECT_EQ(summary_text(s),
            "dynpos live: 123456 bytes, 40 datagrams, 900 lines (800 with a tag block, 2 dropped "
            "for a bad tag block, 1 other datagrams); at most 77 lines (2.3 MB) waited for the "
            "analysis; 12 runs, 0.123 s of processor; 11 JSON lines\n");
}

TEST(LiveSummaryText, AnEmptySession) {
  EXPECT_EQ(summary_text(LiveSummary{}),
            "dynpos live: 0 bytes, 0 datagrams, 0 lines (0 with a tag block, 0 dropped for a bad "
            "tag block, 0 other datagrams); at most 0 lines (0.0 MB) waited for the analysis; 0 "
            "runs, 0.000 s of processor; 0 JSON lines\n");
}

}  // namespace
}  // namespace dynpos::live
