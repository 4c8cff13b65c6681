#pragma once
// The reader thread of a live session (private to the live module): it waits on the stream,
// cuts what arrives into lines (StreamLines) and hands them to a LineQueue at once, so that an
// analysis run, however long, never keeps the socket unread (a UDP socket's buffer would fill
// and the system drop datagrams). It ends the stream: at its end (a TCP server closing), when
// nothing has arrived for the idle time (measured here, by arrival), when asked to stop, or
// at an error (a bad tag block with strict, a followed file cut shorter, the queue's bound),
// which the queue passes on to the consumer.

#include <atomic>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "dynpos/live/stream_lines.hpp"
#include "dynpos/live/stream_source.hpp"
#include "line_queue.hpp"

namespace dynpos::live::detail {

class StreamReader {
 public:
  /// Starts the thread, reading `source` into `queue` (which must outlive this object).
  StreamReader(std::unique_ptr<StreamSource> source, bool strict, std::optional<double> idle_exit_s,
               LineQueue& queue);
  /// Stops the thread (request_stop) and waits for it.
  ~StreamReader();
  StreamReader(const StreamReader&) = delete;
  StreamReader& operator=(const StreamReader&) = delete;

  /// Asks the thread to end the stream (within its poll period); does not wait.
  void request_stop() noexcept { stop_.store(true); }
  /// Waits for the thread to end; then counts() is the whole stream's.
  void join();
  /// What the stream held, as read so far by the thread: valid once join() returned.
  const StreamCounts& counts() const noexcept { return counts_; }

 private:
  void run() noexcept;
  void read_until_end();

  std::unique_ptr<StreamSource> source_;
  std::string name_;
  bool strict_;
  std::optional<double> idle_exit_s_;
  LineQueue& queue_;
  std::atomic<bool> stop_{false};
  StreamCounts counts_;
  std::thread thread_;  // last: started once the members above are made
};

}  // namespace dynpos::live::detail
