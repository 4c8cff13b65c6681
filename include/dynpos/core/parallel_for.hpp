#pragma once
/// \file
/// parallel_for: runs independent pieces of work on several threads, each result in its own slot,
/// so that the output does not depend on the number of threads.

#include <cstddef>
#include <functional>

namespace dynpos::core {

/// The number of threads `jobs` stands for: 0 = every core (at least 1), never more than `n`
/// pieces of work (and at least 1).
unsigned job_count(unsigned jobs, std::size_t n);

/// Calls body(i) for every i in [0, n), on job_count(jobs, n) threads (the calling thread is one
/// of them); pieces are handed out in order of i. body must only write what belongs to piece i.
/// After an exception no new piece starts; the first exception (in time) is rethrown once every
/// thread has stopped.
void parallel_for(std::size_t n, unsigned jobs, const std::function<void(std::size_t)>& body);

}  // namespace dynpos::core
