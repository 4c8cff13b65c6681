#pragma once
// The lines a live session's reader thread hands to its analysis thread (private to the live
// module): a queue that never drops a line. It is unbounded in lines but accounted in bytes;
// past its bound the producer closes it with an error instead of dropping (the session then
// ends with that error). One producer, one consumer; a mutex and a condition variable.

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace dynpos::live::detail {

/// A line as StreamLines passes it on: its text (line end included) and whether it is whole.
struct QueuedLine {
  std::string text;
  bool whole = true;
};

class LineQueue {
 public:
  using Clock = std::chrono::steady_clock;

  /// What the consumer took: every line waiting, and whether the queue is closed and now empty
  /// (error: the producer's exception, to rethrow).
  struct Taken {
    std::vector<QueuedLine> lines;
    bool closed = false;
    std::exception_ptr error;
  };

  /// `max_bytes`: the most bytes that may wait (lines' text plus their bookkeeping).
  explicit LineQueue(std::size_t max_bytes) : max_bytes_(max_bytes) {}

  /// The bytes a line takes in the queue (its accounting).
  static std::size_t cost(const QueuedLine& line) noexcept {
    return line.text.size() + sizeof(QueuedLine);
  }

  /// Producer: appends `lines` (taken from the vector, left empty) and notes their arrival.
  /// Past the bound the queue is closed with an error naming it, and false returned.
  bool push(std::vector<QueuedLine>& lines);
  /// Producer: no more lines; `error` (if any) is what the consumer rethrows.
  void close(std::exception_ptr error = nullptr);

  /// Consumer: waits up to `wait` for a line or the close, then takes everything waiting.
  Taken take(std::chrono::milliseconds wait);
  /// When the last line arrived; unset before the first.
  std::optional<Clock::time_point> last_arrival() const;
  /// The most lines and bytes that waited at once.
  std::size_t peak_lines() const;
  std::size_t peak_bytes() const;

 private:
  mutable std::mutex mutex_;
  std::condition_variable ready_;
  std::vector<QueuedLine> lines_;
  std::size_t bytes_ = 0;
  std::size_t max_bytes_;
  std::size_t peak_lines_ = 0;
  std::size_t peak_bytes_ = 0;
  std::optional<Clock::time_point> last_arrival_;
  bool closed_ = false;
  std::exception_ptr error_;
};

}  // namespace dynpos::live::detail
