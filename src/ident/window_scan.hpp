#pragma once
// Sliding windows over a sampled series (private): each window [tᵢ, tᵢ + w] with its smallest
// and largest value, in linear time, for a range of window starts, so that a day-long input is
// scanned in pieces on several threads.

#include <algorithm>
#include <cstddef>
#include <span>
#include <utility>
#include <vector>

namespace dynpos::ident::detail {

/// A queue of sample indices in a ring of slots that doubles when full: a sliding window's
/// monotone queue, without std::deque's blocks.
class IndexQueue {
 public:
  bool empty() const { return head_ == tail_; }
  std::size_t front() const { return slots_[head_ & mask_]; }
  std::size_t back() const { return slots_[(tail_ - 1) & mask_]; }
  void pop_front() { ++head_; }
  void pop_back() { --tail_; }
  void push_back(std::size_t index) {
    if (tail_ - head_ == slots_.size()) grow();
    slots_[tail_++ & mask_] = index;
  }

 private:
  void grow() {
    std::vector<std::size_t> more(2 * slots_.size());
    for (std::size_t k = head_; k != tail_; ++k) more[k - head_] = slots_[k & mask_];
    tail_ -= head_;
    head_ = 0;
    slots_ = std::move(more);
    mask_ = slots_.size() - 1;
  }

  std::vector<std::size_t> slots_ = std::vector<std::size_t>(64);
  std::size_t mask_ = 63;
  std::size_t head_ = 0, tail_ = 0;  // the queue is [head_, tail_), each taken modulo the slots
};

/// Calls f(i, last, lo, hi) for each window start i in [i0, i1) in turn: the window
/// [tᵢ, tᵢ + w] holds the samples i … last, lo and hi are the smallest and largest of them
/// (monotone queues: linear time). f returns false to stop the scan early.
template <class Values, class F>
void for_each_window(std::span<const double> tv, const Values& uv, double w, std::size_t i0,
                     std::size_t i1, F&& f) {
  const std::size_t n = tv.size();
  IndexQueue max_q;  // indices of decreasing values: front is the window maximum
  IndexQueue min_q;
  std::size_t j = i0;  // one past the window end
  for (std::size_t i = i0; i < i1; ++i) {
    const double t_end = tv[i] + w;
    while (j < n && tv[j] <= t_end) {
      const double uj = uv[j];
      while (!max_q.empty() && uv[max_q.back()] <= uj) max_q.pop_back();
      max_q.push_back(j);
      while (!min_q.empty() && uv[min_q.back()] >= uj) min_q.pop_back();
      min_q.push_back(j);
      ++j;
    }
    while (max_q.front() < i) max_q.pop_front();
    while (min_q.front() < i) min_q.pop_front();
    if (!f(i, j - 1, uv[min_q.front()], uv[max_q.front()])) return;
  }
}

/// The smallest and largest of uv[begin] … uv[end − 1]; begin < end.
template <class Values>
std::pair<double, double> value_bounds(const Values& uv, std::size_t begin, std::size_t end) {
  double lo = uv[begin], hi = uv[begin];
  for (std::size_t k = begin + 1; k < end; ++k) {
    const double x = uv[k];
    lo = x < lo ? x : lo;
    hi = x > hi ? x : hi;
  }
  return {lo, hi};
}

/// The smallest and largest value of each block of `block` samples from i0 on, up to the last
/// sample a window [tᵢ, tᵢ + w] of a start i < i1 holds: the bounds of the values a run of
/// windows can see, so that runs that cannot matter are passed over.
template <class Values>
std::vector<std::pair<double, double>> block_extremes(std::span<const double> tv, const Values& uv,
                                                      double w, std::size_t i0, std::size_t i1,
                                                      std::size_t block) {
  std::size_t end = i1;  // one past the last sample the window of i1 − 1 holds
  while (end < tv.size() && tv[end] <= tv[i1 - 1] + w) ++end;
  std::vector<std::pair<double, double>> out;
  out.reserve((end - i0) / block + 1);
  for (std::size_t b = i0; b < end; b += block) {
    out.push_back(value_bounds(uv, b, std::min(end, b + block)));
  }
  return out;
}

/// The bounds of blocks first … last of block_extremes(): the smallest and largest value.
inline std::pair<double, double> bounds_of(const std::vector<std::pair<double, double>>& blocks,
                                           std::size_t first, std::size_t last) {
  std::pair<double, double> out = blocks[first];
  for (std::size_t k = first + 1; k <= last; ++k) {
    out.first = std::min(out.first, blocks[k].first);
    out.second = std::max(out.second, blocks[k].second);
  }
  return out;
}

/// The shortest piece a scan of a series is cut into (core::piece_count): 16 384 samples.
constexpr std::size_t kShortestScanPiece = 16384;

}  // namespace dynpos::ident::detail
