#pragma once
// A column of numbers appended one at a time without knowing how many will come (private to
// the module): held in blocks of fixed size, so that growing never copies it nor holds twice
// its size, and taken out as one vector block by block, each block returned to the system once
// copied (blocks are mapped pages of their own, not heap memory that may stay with the
// process), so that taking a column out holds it about once, not twice.

#include <sys/mman.h>

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <new>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

namespace dynpos::io::detail {

template <class T>
class ColumnBlocks {
  static_assert(std::is_trivially_copyable_v<T>);

 public:
  static constexpr std::size_t kBlockShift = 17;  // 128 Ki values a block (1 MiB of doubles)
  static constexpr std::size_t kBlockSize = std::size_t{1} << kBlockShift;

  ColumnBlocks() = default;
  ColumnBlocks(ColumnBlocks&& other) noexcept
      : blocks_(std::exchange(other.blocks_, {})), last_(std::exchange(other.last_, kBlockSize)) {}
  ColumnBlocks& operator=(ColumnBlocks&& other) noexcept {
    if (this != &other) {
      clear();
      blocks_ = std::exchange(other.blocks_, {});
      last_ = std::exchange(other.last_, kBlockSize);
    }
    return *this;
  }
  ~ColumnBlocks() { clear(); }

  void push_back(T value) {
    if (last_ == kBlockSize) add_block();
    blocks_.back()[last_++] = value;
  }
  /// Appends `values` (copied a block's room at a time).
  void append(std::span<const T> values) {
    while (!values.empty()) {
      if (last_ == kBlockSize) add_block();
      const std::size_t n = std::min(values.size(), kBlockSize - last_);
      std::memcpy(blocks_.back() + last_, values.data(), n * sizeof(T));
      last_ += n;
      values = values.subspan(n);
    }
  }
  std::size_t size() const noexcept {
    return blocks_.empty() ? 0 : (blocks_.size() - 1) * kBlockSize + last_;
  }
  bool empty() const noexcept { return blocks_.empty(); }
  T operator[](std::size_t k) const noexcept {
    return blocks_[k >> kBlockShift][k & (kBlockSize - 1)];
  }

  /// The values as one vector of U, each through `convert`; each block is freed once copied (the
  /// column is empty after).
  template <class U, class Convert>
  std::vector<U> take(Convert convert) {
    std::vector<U> out;
    out.reserve(size());  // pages are taken as they are written
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
      const std::size_t n = b + 1 == blocks_.size() ? last_ : kBlockSize;
      for (std::size_t i = 0; i < n; ++i) out.push_back(convert(blocks_[b][i]));
      ::munmap(blocks_[b], kBlockBytes);
      blocks_[b] = nullptr;
    }
    clear();
    return out;
  }
  void clear() noexcept {
    for (T* block : blocks_) {
      if (block != nullptr) ::munmap(block, kBlockBytes);
    }
    blocks_.clear();
    blocks_.shrink_to_fit();
    last_ = kBlockSize;
  }

 private:
  static constexpr std::size_t kBlockBytes = kBlockSize * sizeof(T);
  void add_block() {
    blocks_.reserve(blocks_.size() + 1);
    void* block =
        ::mmap(nullptr, kBlockBytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (block == MAP_FAILED) throw std::bad_alloc();
    blocks_.push_back(static_cast<T*>(block));
    last_ = 0;
  }
  std::vector<T*> blocks_;
  std::size_t last_ = kBlockSize;  // values in the last block
};

}  // namespace dynpos::io::detail
