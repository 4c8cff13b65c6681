#include "dynpos/core/parallel_for.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <new>
#include <system_error>
#include <thread>
#include <vector>

namespace dynpos::core {

unsigned job_count(unsigned jobs, std::size_t n) {
  const unsigned wanted = jobs != 0 ? jobs : std::max(1u, std::thread::hardware_concurrency());
  return static_cast<unsigned>(std::max<std::size_t>(1, std::min<std::size_t>(wanted, n)));
}

std::size_t piece_count(std::size_t n, unsigned threads, std::size_t shortest) {
  return std::max<std::size_t>(1, std::min<std::size_t>(threads, n / shortest));
}

std::pair<std::size_t, std::size_t> piece_of(std::size_t n, std::size_t pieces, std::size_t k) {
  return {n * k / pieces, n * (k + 1) / pieces};
}

std::jthread try_start_thread(const std::function<void()>& body) {
  try {
    return std::jthread(body);
  } catch (const std::system_error&) {  // EAGAIN: a limit of memory (a stack) or of processes
    return {};
  } catch (const std::bad_alloc&) {
    return {};
  }
}

void parallel_for(std::size_t n, unsigned jobs, const std::function<void(std::size_t)>& body) {
  const unsigned threads = job_count(jobs, n);
  if (threads <= 1) {
    for (std::size_t i = 0; i < n; ++i) body(i);
    return;
  }
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  std::exception_ptr error;
  std::mutex error_mutex;
  const auto worker = [&] {
    for (std::size_t i = next++; i < n && !stop; i = next++) {
      try {
        body(i);
      } catch (...) {
        const std::lock_guard lock(error_mutex);
        if (!error) error = std::current_exception();
        stop = true;
      }
    }
  };
  {
    std::vector<std::jthread> pool;  // joined on every exit
    pool.reserve(threads - 1);
    for (unsigned j = 1; j < threads; ++j) {
      std::jthread thread = try_start_thread(worker);
      if (!thread.joinable()) break;  // the pieces are shared by the threads there are
      pool.push_back(std::move(thread));
    }
    worker();
  }
  if (error) std::rethrow_exception(error);
}

}  // namespace dynpos::core
