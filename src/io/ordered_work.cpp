#include "ordered_work.hpp"

#include <algorithm>

#include "dynpos/core/parallel_for.hpp"

namespace dynpos::io::detail {

OrderedWork::OrderedWork(unsigned threads, std::size_t slots,
                         std::function<void(std::size_t, unsigned)> work)
    : threads_(threads),
      taker_(threads),
      work_(std::move(work)),
      state_(std::max<std::size_t>(slots, 1), Stage::kFree),
      errors_(state_.size()) {}

OrderedWork::~OrderedWork() {
  {
    const std::lock_guard lock(mutex_);
    stop_ = true;
  }
  changed_.notify_all();
  workers_.clear();  // joins
}

void OrderedWork::start_workers() {
  for (unsigned k = 0; k < threads_; ++k) {
    std::jthread thread = core::try_start_thread([this, k] { worker(k); });
    if (!thread.joinable()) break;  // the taking thread does what no worker takes
    workers_.push_back(std::move(thread));
  }
  threads_ = 0;  // started, once
}

void OrderedWork::queue(std::size_t slot) {
  {
    const std::lock_guard lock(mutex_);
    state_[slot] = Stage::kQueued;
    errors_[slot] = nullptr;
    queued_.push_back(slot);
    ++in_flight_;
  }
  if (in_flight_ >= 2 && threads_ > 0) start_workers();
  changed_.notify_one();
}

void OrderedWork::run(std::size_t slot, unsigned thread, std::unique_lock<std::mutex>& lock) {
  state_[slot] = Stage::kWorking;
  lock.unlock();
  std::exception_ptr error;
  try {
    work_(slot, thread);
  } catch (...) {
    error = std::current_exception();
  }
  lock.lock();
  errors_[slot] = error;
  state_[slot] = Stage::kDone;
}

void OrderedWork::worker(unsigned thread) {
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [this] { return stop_ || !queued_.empty(); });
    if (stop_) return;
    const std::size_t slot = queued_.front();
    queued_.pop_front();
    run(slot, thread, lock);
    changed_.notify_all();
  }
}

void OrderedWork::take(std::size_t slot) {
  std::unique_lock lock(mutex_);
  if (state_[slot] == Stage::kQueued) {
    queued_.erase(std::find(queued_.begin(), queued_.end(), slot));
    run(slot, taker_, lock);
  }
  changed_.wait(lock, [&] { return state_[slot] == Stage::kDone; });
  state_[slot] = Stage::kFree;
  --in_flight_;
  if (errors_[slot]) std::rethrow_exception(std::exchange(errors_[slot], nullptr));
}

}  // namespace dynpos::io::detail
