#include "stream_reader.hpp"

#include <poll.h>

#include <chrono>
#include <utility>
#include <vector>

namespace dynpos::live::detail {
namespace {

/// The longest wait of the reader [ms]: how often a followed file is looked at, and how soon
/// a stop or the idle time is seen.
constexpr int kPoll_ms = 100;

}  // namespace

StreamReader::StreamReader(std::unique_ptr<StreamSource> source, bool strict,
                           std::optional<double> idle_exit_s, LineQueue& queue)
    : source_(std::move(source)),
      name_(source_->name()),
      strict_(strict),
      idle_exit_s_(idle_exit_s),
      queue_(queue),
      thread_([this] { run(); }) {}

StreamReader::~StreamReader() {
  request_stop();
  join();
}

void StreamReader::join() {
  if (thread_.joinable()) thread_.join();
}

void StreamReader::run() noexcept {
  try {
    read_until_end();
    queue_.close();
  } catch (...) {
    queue_.close(std::current_exception());
  }
}

void StreamReader::read_until_end() {
  using Clock = std::chrono::steady_clock;
  std::vector<QueuedLine> batch;
  StreamLines lines(name_, strict_, [&batch](std::string_view line, bool whole) {
    batch.push_back({std::string(line), whole});
  });
  auto last_data = Clock::now();
  bool open = true;
  while (open && !stop_.load()) {
    pollfd fd{source_->fd(), POLLIN, 0};
    ::poll(&fd, fd.fd >= 0 ? 1 : 0, kPoll_ms);
    const std::size_t before = lines.counts().bytes;
    open = source_->read(lines);
    if (lines.counts().bytes != before) last_data = Clock::now();
    if (!open) lines.finish();
    counts_ = lines.counts();
    if (!queue_.push(batch)) return;  // closed with an error, which the consumer rethrows
    const double quiet_s = std::chrono::duration<double>(Clock::now() - last_data).count();
    if (idle_exit_s_ && quiet_s >= *idle_exit_s_) break;
  }
  if (open) source_->read(lines);  // stopped or idle: what is already there still counts
  lines.finish();
  counts_ = lines.counts();
  queue_.push(batch);
}

}  // namespace dynpos::live::detail
