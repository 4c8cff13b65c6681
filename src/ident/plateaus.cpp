#include "plateaus.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "dynpos/core/parallel_for.hpp"
#include "series.hpp"
#include "window_scan.hpp"

namespace dynpos::ident::detail {
namespace {

double median_of(std::span<const double> x, std::size_t begin, std::size_t end) {
  return median(std::vector<double>(x.begin() + static_cast<std::ptrdiff_t>(begin),
                                    x.begin() + static_cast<std::ptrdiff_t>(end) + 1));
}

// First index of the samples within `w` [s] before index `last` (dir −1), or last index of
// those within `w` after `first` (dir +1).
std::size_t reach(std::span<const double> tv, std::size_t from, std::size_t stop, double w,
                  int dir) {
  std::size_t k = from;
  if (dir < 0) {
    while (k > stop && tv[k - 1] >= tv[from] - w) --k;
  } else {
    while (k < stop && tv[k + 1] <= tv[from] + w) ++k;
  }
  return k;
}

// The levels of a plateau: the medians of its first and last w/2 (next to a transition) and of
// its first and last 20w (the levels a step goes from and to: long enough to average the noise,
// short enough that a drift or a merged small change far from the step does not move them). A
// plateau window may take in the first or last 2h of a ramp, so the edge samples more than h
// from the median of the plateau's nearest w are left out.
void set_levels(Plateau& p, std::span<const double> tv, std::span<const double> uv, double h,
                double w) {
  std::size_t first = p.begin;
  std::size_t last = p.end;
  while (tv[last] - tv[first] > w) {
    if (std::abs(uv[last] - median_of(uv, reach(tv, last, first, w, -1), last)) <= h) break;
    --last;
  }
  while (tv[last] - tv[first] > w) {
    if (std::abs(uv[first] - median_of(uv, first, reach(tv, first, last, w, +1))) <= h) break;
    ++first;
  }
  p.start_level = median_of(uv, first, reach(tv, first, last, 0.5 * w, +1));
  p.end_level = median_of(uv, reach(tv, last, first, 0.5 * w, -1), last);
  p.head_level = median_of(uv, first, reach(tv, first, last, 20.0 * w, +1));
  p.tail_level = median_of(uv, reach(tv, last, first, 20.0 * w, -1), last);
}

// The plateau rule, fed one window at a time. Its state is the last plateau's end and the level
// it started at: two scans in the same state move alike on the same windows.
struct PlateauScan {
  std::span<const double> tv;
  double h = 0.0, w = 0.0;
  std::vector<Plateau> plateaus;
  std::vector<double> refs;          // each plateau's first window level
  std::vector<std::size_t> started;  // the window (its first sample) that started each plateau

  void add(std::size_t i, std::size_t last, double lo, double hi) {
    // A window cut short by a gap or the end of the log must still span half the duration.
    if (tv[last] - tv[i] < 0.5 * w || hi - lo > 2.0 * h) return;
    const double mid = 0.5 * (hi + lo);
    if (!plateaus.empty() && i <= plateaus.back().end + 1 && std::abs(mid - refs.back()) <= h) {
      plateaus.back().end = std::max(plateaus.back().end, last);
      return;
    }
    const std::size_t begin = plateaus.empty() ? i : std::max(i, plateaus.back().end + 1);
    if (begin > last) return;
    plateaus.push_back({begin, last});
    refs.push_back(mid);
    started.push_back(i);
  }
};

// Whether every window whose samples lie in [lo, hi] holds the current plateau's level: within
// 2h of each other and ±h of its first level. Values within half the largest double keep a
// window's mid-level 0.5·(hi + lo) finite and inside [lo, hi], as the window-by-window rule
// computes it.
bool holds_level(const PlateauScan& scan, double lo, double hi) {
  constexpr double kHalfMax = 0.5 * std::numeric_limits<double>::max();
  if (scan.plateaus.empty() || !(std::abs(lo) <= kHalfMax && std::abs(hi) <= kHalfMax)) {
    return false;
  }
  const double ref = scan.refs.back();
  return hi - lo <= 2.0 * scan.h && std::max(std::abs(lo - ref), std::abs(hi - ref)) <= scan.h;
}

// Scans the windows starting in [i0, i1) a block at a time, until stop(i) is true after window
// i (it is asked after every window scanned one by one and after every block passed whole); the
// window it stopped after, or i1. A block whose windows all hold the current plateau's level
// (holds_level) needs no window's extremes, only where each window ends: it extends the
// plateau, or, after a gap, ends the shortcut there. The rest are scanned window by window. The
// result is the window-by-window scan's; a held level is passed at the speed of reading it.
template <class Stop>
std::size_t scan_range(PlateauScan& scan, std::span<const double> uv, std::size_t i0,
                       std::size_t i1, Stop&& stop) {
  constexpr std::size_t kBlock = 4096;
  const std::span<const double> tv = scan.tv;
  const double w = scan.w;
  std::size_t stopped = i1;
  const auto add = [&](std::size_t i, std::size_t last, double lo, double hi) {
    scan.add(i, last, lo, hi);
    if (stop(i)) stopped = i;
    return stopped == i1;
  };
  std::size_t j = i0;  // one past the last sample of the current window
  for (std::size_t b0 = i0; b0 < i1; b0 += kBlock) {
    const std::size_t b1 = std::min(i1, b0 + kBlock);
    std::size_t window_end = std::max(j, b1);  // one past the window of b1 − 1
    while (window_end < tv.size() && tv[window_end] <= tv[b1 - 1] + w) ++window_end;
    const auto [lo, hi] = value_bounds(uv, b0, window_end);  // what its windows can hold
    std::size_t i = b0;
    for (const bool held = holds_level(scan, lo, hi); held && i < b1; ++i) {
      while (j < tv.size() && tv[j] <= tv[i] + w) ++j;
      const std::size_t last = j - 1;
      if (tv[last] - tv[i] < 0.5 * w) continue;     // cut short by a gap: no plateau window
      if (i > scan.plateaus.back().end + 1) break;  // a new plateau: its level is needed
      scan.plateaus.back().end = std::max(scan.plateaus.back().end, last);
    }
    if (i < b1) {
      for_each_window(tv, uv, w, i, b1, add);
    } else if (stop(b1 - 1)) {
      stopped = b1 - 1;
    }
    if (stopped != i1) return stopped;
    j = std::max(j, b1);
  }
  return i1;
}

// Carries `whole` (the scan of every window before piece [i0, i1)) through the piece, given
// `local`, the piece scanned from an empty state. Once both hold a plateau started at the same
// level, their ends agree too (each is the last sample of the newest window that held a level),
// and then they move alike: from there on the piece's own plateaus are the whole scan's. Only
// the windows before that are scanned again (up to the first step in the piece, as a rule; the
// whole piece, held levels passed by blocks, for an input that holds one level throughout it).
void join_piece(PlateauScan& whole, const PlateauScan& local, std::span<const double> uv,
                std::size_t i0, std::size_t i1) {
  std::size_t started = 0;  // local plateaus started by window i
  const auto same_state = [&](std::size_t i) {
    while (started < local.started.size() && local.started[started] <= i) ++started;
    return started > 0 && !whole.plateaus.empty() && whole.refs.back() == local.refs[started - 1];
  };
  if (scan_range(whole, uv, i0, i1, same_state) == i1) return;  // the piece scanned whole
  whole.plateaus.back().end = local.plateaus[started - 1].end;
  for (std::size_t k = started; k < local.plateaus.size(); ++k) {
    whole.plateaus.push_back(local.plateaus[k]);
    whole.refs.push_back(local.refs[k]);
    whole.started.push_back(local.started[k]);
  }
}

}  // namespace

std::vector<Plateau> find_plateaus(std::span<const double> tv, std::span<const double> uv, double h,
                                   double w, unsigned jobs) {
  const std::size_t n = tv.size();
  const std::size_t pieces = core::piece_count(n, core::job_count(jobs, n), kShortestScanPiece);
  std::vector<PlateauScan> scans(pieces, PlateauScan{tv, h, w, {}, {}, {}});
  core::parallel_for(pieces, jobs, [&](std::size_t k) {
    const auto [i0, i1] = core::piece_of(n, pieces, k);
    PlateauScan scan{tv, h, w, {}, {}, {}};  // a local: neighbouring slots share cache lines
    scan_range(scan, uv, i0, i1, [](std::size_t) { return false; });
    scans[k] = std::move(scan);
  });
  PlateauScan whole = std::move(scans.front());
  for (std::size_t k = 1; k < pieces; ++k) {
    const auto [i0, i1] = core::piece_of(n, pieces, k);
    join_piece(whole, scans[k], uv, i0, i1);
  }
  // Levels next to a transition over w/2: on a drift slow enough to hold plateaus (2h per w)
  // they differ by at most h, half the smallest threshold.
  std::vector<Plateau>& plateaus = whole.plateaus;
  core::parallel_for(plateaus.size(), jobs,
                     [&](std::size_t p) { set_levels(plateaus[p], tv, uv, h, w); });
  return plateaus;
}

std::vector<Plateau> merge_levels(const std::vector<Plateau>& in, std::span<const double> tv,
                                  std::span<const double> uv, double h, double threshold,
                                  const StepDetectorOptions& options) {
  std::vector<Plateau> out;
  for (const Plateau& p : in) {
    if (!out.empty()) {
      Plateau& back = out.back();
      const double change = p.start_level - back.end_level;
      bool merge = std::abs(change) < threshold;
      bool settle = false;
      if (!merge && out.size() >= 2) {
        const double step = back.start_level - out[out.size() - 2].end_level;
        settle = tv[back.end] - tv[back.begin] < options.settle_s && change * step < 0.0 &&
                 std::abs(change) < options.settle_fraction * std::abs(step);
      }
      if (merge || settle) {
        back.end = p.end;
        set_levels(back, tv, uv, h, options.min_plateau_s);
        if (settle) back.head_level = p.head_level;  // the settled level
        continue;
      }
    }
    out.push_back(p);
  }
  return out;
}

}  // namespace dynpos::ident::detail
