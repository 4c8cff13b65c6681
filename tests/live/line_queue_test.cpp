// The queue between a live session's reader and analysis threads, and the reader on a followed
// file: every line comes through, in order; the bound is an error, never a loss.

#include "line_queue.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "dynpos/live/stream_source.hpp"
#include "live_fixtures.hpp"
#include "stream_reader.hpp"

namespace dynpos::live::detail {
namespace {

using namespace std::chrono_literals;

// Takes every line until the queue is closed; rethrows its error.
std::vector<std::string> take_all(LineQueue& queue) {
  std::vector<std::string> got;
  for (;;) {
    LineQueue::Taken taken = queue.take(100ms);
    if (taken.error) std::rethrow_exception(taken.error);
    for (const QueuedLine& line : taken.lines) got.push_back(line.text);
    if (taken.closed) return got;
  }
}

TEST(LineQueue, EveryLineComesThroughInOrder) {
  LineQueue queue(std::size_t{1} << 30);
  constexpr int kLines = 20000;
  std::thread producer([&] {
    std::vector<QueuedLine> batch;
    for (int i = 0; i < kLines; ++i) {
      batch.push_back({std::to_string(i) + "\n", true});
      if (i % 7 == 0) {
        EXPECT_TRUE(queue.push(batch));
        EXPECT_TRUE(batch.empty());
      }
    }
    EXPECT_TRUE(queue.push(batch));
    queue.close();
  });
  const std::vector<std::string> got = take_all(queue);
  producer.join();
  ASSERT_EQ(got.size(), static_cast<std::size_t>(kLines));
  for (int i = 0; i < kLines; ++i)
    EXPECT_EQ(got[static_cast<std::size_t>(i)], std::to_string(i) + "\n");
  EXPECT_GE(queue.peak_lines(), 1u);
  EXPECT_GE(queue.peak_bytes(), queue.peak_lines() * sizeof(QueuedLine));
  EXPECT_TRUE(queue.last_arrival().has_value());
}

TEST(LineQueue, PastItsBoundItIsClosedWithAnError) {
  LineQueue queue(10 * LineQueue::cost({"x\n", true}));
  std::vector<QueuedLine> batch(9, QueuedLine{"x\n", true});
  EXPECT_TRUE(queue.push(batch));
  batch.assign(2, QueuedLine{"x\n", true});
  EXPECT_FALSE(queue.push(batch));  // 11 would wait: an error, not a drop
  EXPECT_THROW(take_all(queue), std::runtime_error);
}

TEST(LineQueue, TheProducersErrorReachesTheConsumer) {
  LineQueue queue(1 << 20);
  queue.close(std::make_exception_ptr(std::invalid_argument("bad tag block")));
  EXPECT_THROW(take_all(queue), std::invalid_argument);
}

// The reader on a followed file: what is there and what is appended, then the idle time ends it.
TEST(StreamReader, ReadsAFollowedFileUntilIdle) {
  test::TempDir dir;
  const auto file = dir / "grow.csv";
  test::write_lines(file, {"time,x\n", "0,1\n"});
  LineQueue queue(1 << 20);
  StreamReader reader(follow_file(file, "follow"), false, 0.5, queue);
  std::this_thread::sleep_for(20ms);
  std::ofstream(file, std::ios::app) << "1,2\n";
  const std::vector<std::string> got = take_all(queue);
  reader.join();
  EXPECT_EQ(got, (std::vector<std::string>{"time,x\n", "0,1\n", "1,2\n"}));
  EXPECT_EQ(reader.counts().lines, 3u);
}

TEST(StreamReader, AStopRequestEndsTheStream) {
  test::TempDir dir;
  const auto file = dir / "log.csv";
  test::write_lines(file, {"time,x\n"});
  LineQueue queue(1 << 20);
  StreamReader reader(follow_file(file, "follow"), false, std::nullopt, queue);
  reader.request_stop();
  EXPECT_EQ(take_all(queue), (std::vector<std::string>{"time,x\n"}));
}

}  // namespace
}  // namespace dynpos::live::detail
