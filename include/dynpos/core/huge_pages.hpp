#pragma once
/// \file
/// Huge pages for long buffers: a day-long log's columns are hundreds of megabytes, and touching
/// fresh memory in 4 KiB pages costs a page fault each (on a virtual machine, more than the
/// parsing). Advising the kernel to back a buffer with 2 MiB pages before it is first written
/// cuts the faults 512-fold; where the kernel does not offer them it changes nothing.

#include <cstddef>
#include <vector>

namespace dynpos::core {

/// Advises huge pages for the whole 2 MiB pages inside [data, data + bytes). Call it before the
/// memory is first written; it never fails (advice only).
void advise_huge_pages(const void* data, std::size_t bytes) noexcept;

/// v.reserve(n), with huge pages advised for the new storage.
template <class T>
void reserve_huge(std::vector<T>& v, std::size_t n) {
  if (n <= v.capacity()) return;
  v.reserve(n);
  advise_huge_pages(v.data() + v.size(), (v.capacity() - v.size()) * sizeof(T));
}

}  // namespace dynpos::core
