#pragma once
// Counts heap allocations, so a test can show that a step or a run allocates nothing (or no
// more than a fixed amount). Replaces the global operator new/delete: include it in exactly
// one source file of a test executable.

#include <atomic>
#include <cstdlib>
#include <new>

namespace dynpos::test {
inline std::atomic<long> g_allocations{0};
}  // namespace dynpos::test

// Out of line, so that GCC does not pair an inlined malloc() or free() with operator new or
// delete and warn about a mismatch.
[[gnu::noinline]] void* operator new(std::size_t size) {
  ++dynpos::test::g_allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
[[gnu::noinline]] void operator delete(void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept { std::free(p); }
