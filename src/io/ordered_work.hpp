#pragma once
// Work on a ring of slots done by worker threads and taken back in the order it was queued
// (private to the module): the MCAP reader's chunks are read, decompressed and checked ahead of
// the thread that hands their messages on, in file order.

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace dynpos::io::detail {

/// Up to `slots` pieces of work in flight, done by up to `threads` worker threads (started when
/// a second piece is queued before the first is taken, so that a file of one chunk starts
/// none). The caller queues slots in a ring order and takes them back in the same order; a
/// piece no worker has started yet is done by the taking thread itself. With threads == 0 every
/// piece is done by the taking thread, in order. The work is told the slot and which thread does
/// it: worker k in [0, threads), or `threads` for the taking thread (for what each thread keeps
/// from piece to piece, such as a decompression context).
class OrderedWork {
 public:
  OrderedWork(unsigned threads, std::size_t slots,
              std::function<void(std::size_t slot, unsigned thread)> work);
  /// Stops the workers (each finishes the piece it is on) and joins them.
  ~OrderedWork();
  OrderedWork(const OrderedWork&) = delete;
  OrderedWork& operator=(const OrderedWork&) = delete;

  std::size_t slots() const noexcept { return state_.size(); }
  /// The pieces queued and not yet taken back.
  std::size_t in_flight() const noexcept { return in_flight_; }
  /// Queues the piece of `slot` (free: never queued, or taken back).
  void queue(std::size_t slot);
  /// Waits for the piece of `slot` (the oldest one in flight) to be done, doing it here when no
  /// worker has started it; the slot is free again. Rethrows what the work threw.
  void take(std::size_t slot);

 private:
  enum class Stage : unsigned char { kFree, kQueued, kWorking, kDone };
  void start_workers();
  void worker(unsigned thread);
  // Runs the work of `slot` on `thread` and records its end (with `lock` held on entry and exit).
  void run(std::size_t slot, unsigned thread, std::unique_lock<std::mutex>& lock);

  unsigned threads_;  // the workers to start; 0 once started
  unsigned taker_;    // the taking thread's number: the workers asked for
  std::function<void(std::size_t, unsigned)> work_;
  std::vector<Stage> state_;
  std::vector<std::exception_ptr> errors_;
  std::deque<std::size_t> queued_;  // in queue order
  std::size_t in_flight_ = 0;
  bool stop_ = false;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<std::jthread> workers_;
};

}  // namespace dynpos::io::detail
