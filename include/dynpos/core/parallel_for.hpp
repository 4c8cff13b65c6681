#pragma once
/// \file
/// parallel_for: runs independent pieces of work on several threads, each result in its own slot,
/// so that the output does not depend on the number of threads.

#include <cstddef>
#include <functional>
#include <thread>
#include <utility>

namespace dynpos::core {

/// The one default of every thread count a user sets (`jobs` of a request or of options, the
/// CLI's --jobs, the Python API's jobs=): 0, every core. Results never depend on it. Functions
/// that work inside a piece of a parallel loop take their count explicitly (usually 1).
inline constexpr unsigned kEveryCore = 0;

/// The number of threads `jobs` stands for: 0 = every core (at least 1), never more than `n`
/// pieces of work (and at least 1).
unsigned job_count(unsigned jobs, std::size_t n);

/// How many pieces a series of n items is cut into for `threads` threads: none shorter than
/// `shortest` items (a shorter one costs more to hand out than to work through), at least one.
std::size_t piece_count(std::size_t n, unsigned threads, std::size_t shortest);

/// Piece k of [0, n) cut into `pieces` nearly equal pieces: [first, last).
std::pair<std::size_t, std::size_t> piece_of(std::size_t n, std::size_t pieces, std::size_t k);

/// `body` started on a new thread; or, when the system cannot make one (std::system_error with
/// EAGAIN under a memory limit such as `ulimit -v`, or a limit of processes; std::bad_alloc), a
/// thread that is not joinable and never ran `body`: the caller does the work itself.
std::jthread try_start_thread(const std::function<void()>& body);

/// Calls body(i) for every i in [0, n), on up to job_count(jobs, n) threads (the calling thread
/// is one of them; when the system cannot start more, on those it could, the results being the
/// same); pieces are handed out in order of i. body must only write what belongs to piece i;
/// what it updates over and over is best kept in a local and stored once at the end, since
/// neighbouring slots share cache lines and threads writing one line slow each other down.
/// After an exception no new piece starts; the first exception (in time) is rethrown once every
/// thread has stopped.
void parallel_for(std::size_t n, unsigned jobs, const std::function<void(std::size_t)>& body);

}  // namespace dynpos::core
