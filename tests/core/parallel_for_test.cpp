// parallel_for: every piece exactly once, whatever the number of threads, and the same when the
// system cannot start a thread (a memory limit such as `ulimit -v`, or a limit of processes).

#include "dynpos/core/parallel_for.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <atomic>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

namespace dynpos::core {
namespace {

// The sum of the squares of 0 … n−1, each piece writing its own slot.
unsigned long long sum_of_squares(std::size_t n, unsigned jobs) {
  std::vector<unsigned long long> slot(n, 0);
  parallel_for(n, jobs, [&](std::size_t i) { slot[i] = static_cast<unsigned long long>(i) * i; });
  unsigned long long sum = 0;
  for (const unsigned long long v : slot) sum += v;
  return sum;
}

TEST(ParallelFor, EveryPieceOnceWhateverTheJobs) {
  const unsigned long long expected = 999ull * 1000ull * 1999ull / 6ull;  // Σ i², i < 1000
  for (const unsigned jobs : {1u, 2u, 3u, 8u, 0u}) EXPECT_EQ(sum_of_squares(1000, jobs), expected);
}

#if defined(__SANITIZE_ADDRESS__)
#define DYNPOS_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define DYNPOS_ADDRESS_SANITIZER 1
#endif
#endif

#ifndef DYNPOS_ADDRESS_SANITIZER
// The process's address space now [bytes], from /proc/self/status.
std::size_t address_space_bytes() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);) {
    if (line.rfind("VmSize:", 0) == 0) return std::stoull(line.substr(7)) * 1024;
  }
  return 0;
}

// Limits the process to its address space plus 4 MiB, where no thread can get its stack (8 MiB
// by default), then runs 1000 pieces on 8 jobs; exits 0 when no thread started and every piece
// was done, 1 otherwise.
[[noreturn]] void run_without_threads() {
  const rlimit limit{address_space_bytes() + (4u << 20), RLIM_INFINITY};
  if (setrlimit(RLIMIT_AS, &limit) != 0) std::exit(3);
  const bool none = !try_start_thread([] {}).joinable();
  const bool sum = sum_of_squares(1000, 8) == 999ull * 1000ull * 1999ull / 6ull;
  std::exit(none && sum ? 0 : 1);
}
#endif

// In a child process the threads fail to start (std::system_error, EAGAIN) and the calling
// thread does every piece. It used to end the process (an uncaught std::system_error).
TEST(ParallelForDeathTest, WithoutThreadsTheCallerDoesEveryPiece) {
#ifdef DYNPOS_ADDRESS_SANITIZER
  GTEST_SKIP() << "an address-space limit and AddressSanitizer's shadow memory do not mix";
#else
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(run_without_threads(), ::testing::ExitedWithCode(0), "");
#endif
}

}  // namespace
}  // namespace dynpos::core
