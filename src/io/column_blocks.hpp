#pragma once
// A column of numbers appended one at a time without knowing how many will come (private to
// the module): held in blocks of fixed size, so that growing never copies it nor holds twice
// its size, and taken out as one vector block by block, each block returned to the system once
// copied (blocks are mapped pages of their own, not heap memory that may stay with the
// process), so that taking a column out holds it about once, not twice. When the number is
// known beforehand (a hint: reserve()), the values go into one vector of that room first, which
// take() hands out as it is when nothing went past it: written once, never copied.

#include <sys/mman.h>

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <new>
#include <span>
#include <stdexcept>
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
      : front_(std::exchange(other.front_, {})),
        blocks_(std::exchange(other.blocks_, {})),
        last_(std::exchange(other.last_, kBlockSize)) {}
  ColumnBlocks& operator=(ColumnBlocks&& other) noexcept {
    if (this != &other) {
      clear();
      front_ = std::exchange(other.front_, {});
      blocks_ = std::exchange(other.blocks_, {});
      last_ = std::exchange(other.last_, kBlockSize);
    }
    return *this;
  }
  ~ColumnBlocks() { clear(); }

  /// Room for the first n values in one vector (its pages taken as they are written), while the
  /// column is empty; none when the system refuses it (n is only a hint).
  void reserve(std::size_t n) {
    if (!empty()) return;
    try {
      front_.reserve(n);
    } catch (const std::bad_alloc&) {
    } catch (const std::length_error&) {
    }
  }
  void push_back(T value) {
    if (blocks_.empty() && front_.size() < front_.capacity()) {
      front_.push_back(value);
      return;
    }
    if (last_ == kBlockSize) add_block();
    blocks_.back()[last_++] = value;
  }
  /// Appends `values` (copied a block's room at a time).
  void append(std::span<const T> values) {
    if (blocks_.empty()) {
      const std::size_t n = std::min(values.size(), front_.capacity() - front_.size());
      front_.insert(front_.end(), values.begin(), values.begin() + static_cast<std::ptrdiff_t>(n));
      values = values.subspan(n);
    }
    while (!values.empty()) {
      if (last_ == kBlockSize) add_block();
      const std::size_t n = std::min(values.size(), kBlockSize - last_);
      std::memcpy(blocks_.back() + last_, values.data(), n * sizeof(T));
      last_ += n;
      values = values.subspan(n);
    }
  }
  std::size_t size() const noexcept {
    return front_.size() + (blocks_.empty() ? 0 : (blocks_.size() - 1) * kBlockSize + last_);
  }
  bool empty() const noexcept { return size() == 0; }
  T operator[](std::size_t k) const noexcept {
    if (k < front_.size()) return front_[k];
    k -= front_.size();
    return blocks_[k >> kBlockShift][k & (kBlockSize - 1)];
  }

  /// The values as one vector of U, each through `convert`; each block is freed once copied (the
  /// column is empty after).
  template <class U, class Convert>
  std::vector<U> take(Convert convert) {
    std::vector<U> out;
    out.reserve(size());  // pages are taken as they are written
    for (const T value : front_) out.push_back(convert(value));
    std::vector<T>().swap(front_);
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
      const std::size_t n = b + 1 == blocks_.size() ? last_ : kBlockSize;
      for (std::size_t i = 0; i < n; ++i) out.push_back(convert(blocks_[b][i]));
      ::munmap(blocks_[b], kBlockBytes);
      blocks_[b] = nullptr;
    }
    clear();
    return out;
  }
  /// The values as one vector: the reserved one itself when they all went into it and filled
  /// most of it (a hint far too large is not kept: they are copied out then).
  std::vector<T> take() {
    if (blocks_.empty() && front_.capacity() - front_.size() <= front_.size() / 8) {
      return std::exchange(front_, {});
    }
    return take<T>([](T value) { return value; });
  }
  void clear() noexcept {
    std::vector<T>().swap(front_);
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

  std::vector<T> front_;  // the reserved room, filled first
  std::vector<T*> blocks_;
  std::size_t last_ = kBlockSize;  // values in the last block
};

}  // namespace dynpos::io::detail
