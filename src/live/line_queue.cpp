#include "line_queue.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <iterator>
#include <stdexcept>

namespace dynpos::live::detail {

bool LineQueue::push(std::vector<QueuedLine>& lines) {
  if (lines.empty()) return true;
  std::size_t added = 0;
  for (const QueuedLine& line : lines) added += cost(line);
  bool accepted = true;
  bool notify = false;
  {
    const std::lock_guard lock(mutex_);
    if (closed_) return false;
    if (bytes_ + added > max_bytes_) {
      error_ = std::make_exception_ptr(std::runtime_error(fmt::format(
          "the lines waiting for the analysis ({} lines, {:.0f} MB) reached the bound of "
          "{:.0f} MB: the analysis cannot keep up with the stream; give a longer --update, or "
          "send the stream no faster than real time",
          lines_.size() + lines.size(), static_cast<double>(bytes_ + added) / 1e6,
          static_cast<double>(max_bytes_) / 1e6)));
      closed_ = true;
      accepted = false;
      notify = true;
    } else {
      notify = lines_.empty();  // else the consumer was told when the first of them came
      lines_.insert(lines_.end(), std::make_move_iterator(lines.begin()),
                    std::make_move_iterator(lines.end()));
      bytes_ += added;
      peak_lines_ = std::max(peak_lines_, lines_.size());
      peak_bytes_ = std::max(peak_bytes_, bytes_);
      last_arrival_ = Clock::now();
    }
  }
  lines.clear();
  if (notify) ready_.notify_one();
  return accepted;
}

void LineQueue::close(std::exception_ptr error) {
  {
    const std::lock_guard lock(mutex_);
    if (!error_) error_ = std::move(error);
    closed_ = true;
  }
  ready_.notify_one();
}

LineQueue::Taken LineQueue::take(std::chrono::milliseconds wait) {
  std::unique_lock lock(mutex_);
  ready_.wait_for(lock, wait, [this] { return closed_ || !lines_.empty(); });
  Taken taken;
  taken.lines.swap(lines_);
  bytes_ = 0;
  taken.closed = closed_;
  taken.error = error_;
  return taken;
}

std::optional<LineQueue::Clock::time_point> LineQueue::last_arrival() const {
  const std::lock_guard lock(mutex_);
  return last_arrival_;
}

std::size_t LineQueue::peak_lines() const {
  const std::lock_guard lock(mutex_);
  return peak_lines_;
}

std::size_t LineQueue::peak_bytes() const {
  const std::lock_guard lock(mutex_);
  return peak_bytes_;
}

}  // namespace dynpos::live::detail
