#include "ordered_work.hpp"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <vector>

namespace dynpos::io::detail {
namespace {

// Each piece is done once, by a worker (0 … threads - 1) or by the taking thread (`threads`),
// and taken back in the order it was queued; an error is rethrown by the take of its piece.
TEST(OrderedWork, TellsTheWorkWhichThreadDoesItAndTakesPiecesInOrder) {
  for (const unsigned threads : {0u, 1u, 3u}) {
    const std::size_t slots = 2 * std::size_t{threads} + 1;
    std::vector<int> piece(slots, -1);
    std::vector<unsigned> by(slots, 99);
    int next = 0;
    OrderedWork work(threads, slots, [&](std::size_t slot, unsigned thread) {
      by[slot] = thread;
      if (piece[slot] == 40) throw std::runtime_error("piece 40");
    });
    std::set<unsigned> seen;
    int taken = 0;
    std::size_t ring = 0;
    const auto queue = [&] {
      while (work.in_flight() < work.slots()) {
        piece[ring] = next++;
        work.queue(ring);
        ring = (ring + 1) % slots;
      }
    };
    queue();
    for (std::size_t head = 0; taken < 60; head = (head + 1) % slots) {
      if (piece[head] == 40) {
        EXPECT_THROW(work.take(head), std::runtime_error);
      } else {
        work.take(head);
      }
      ASSERT_EQ(piece[head], taken++) << threads << " threads";
      ASSERT_LE(by[head], threads);
      seen.insert(by[head]);
      queue();
    }
    if (threads == 0) {
      EXPECT_EQ(seen, std::set<unsigned>{0u});
    }
  }
}

}  // namespace
}  // namespace dynpos::io::detail
