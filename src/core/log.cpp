#include "dynpos/core/log.hpp"

#include <algorithm>
#include <cstdio>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <utility>

#include "dynpos/core/parallel_for.hpp"
#include "dynpos/core/time_order.hpp"
#include "dynpos/core/time_spacing.hpp"

namespace dynpos::core {

std::size_t missing_count(std::span<const double> values, unsigned jobs) {
  constexpr std::size_t kShortest = 1 << 18;  // a piece is counted in about 0.1 ms
  const std::size_t n = values.size();
  const std::size_t pieces = piece_count(n, job_count(jobs, n), kShortest);
  std::vector<std::size_t> missing(pieces);
  parallel_for(pieces, jobs, [&](std::size_t k) {
    const auto [first, last] = piece_of(n, pieces, k);
    const std::span<const double> piece = values.subspan(first, last - first);
    missing[k] = static_cast<std::size_t>(std::count_if(piece.begin(), piece.end(), is_missing));
  });
  std::size_t total = 0;
  for (const std::size_t m : missing) total += m;
  return total;
}

namespace {

// Compact text of a time or value for messages.
std::string num(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.10g", x);
  return buffer;
}

std::string single_quoted(std::string_view name) { return "'" + std::string(name) + "'"; }

// Throws std::invalid_argument unless every time is finite and strictly increasing.
void check_time_axis(const std::vector<double>& time_s, std::string_view context, unsigned jobs) {
  const std::size_t i = first_unordered_time(time_s, jobs);
  if (i == time_s.size()) return;
  if (!std::isfinite(time_s[i])) {
    throw std::invalid_argument(std::string(context) + ": time[" + std::to_string(i) +
                                "] = " + num(time_s[i]) + " is not finite");
  }
  throw std::invalid_argument(std::string(context) + ": time is not strictly increasing at index " +
                              std::to_string(i) + " (" + num(time_s[i - 1]) + " s then " +
                              num(time_s[i]) + " s); sort the samples and drop duplicate times");
}

// The range [lo, lo + 2π) an angle channel's interpolated values are put back in, from its valid
// samples (see Interp::kAngle); nullopt for an unwrapped series, which is left as it comes.
std::optional<double> angle_range_start(const std::vector<double>& values) {
  constexpr double kPi = std::numbers::pi;
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  if (*lo >= 0.0 && *hi <= 2.0 * kPi) return 0.0;
  if (*lo >= -kPi && *hi <= kPi) return -kPi;
  return std::nullopt;
}

// Linear interpolation of an angle along the shorter arc, wrapped into [range_start,
// range_start + 2π) when there is a range. For |ψ₁ − ψ₀| < π the difference is unchanged
// (std::remainder is exact), so a series that never jumps gets the kLinear values bit for bit.
double interpolate_angle(double v0, double v1, double fraction,
                         const std::optional<double>& range_start) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  double v = v0 + std::remainder(v1 - v0, kTwoPi) * fraction;
  if (range_start) {
    if (v < *range_start) v += kTwoPi;
    if (v >= *range_start + kTwoPi) v -= kTwoPi;
  }
  return v;
}

// One channel onto the target axis in O(N + M): the valid samples are gathered once, then a
// single pointer into them advances monotonically as the (increasing) target times advance.
std::vector<double> resample_channel(const std::vector<double>& time_s, const Channel& channel,
                                     const std::vector<double>& target_s, double max_gap_s) {
  if (channel.values.size() != time_s.size()) {
    throw std::invalid_argument("resample: channel " + single_quoted(channel.name) + " has " +
                                std::to_string(channel.values.size()) + " values but the log has " +
                                std::to_string(time_s.size()) + " time samples");
  }
  std::vector<double> out(target_s.size(), kMissing);
  std::vector<double> valid_t;
  std::vector<double> valid_v;
  for (std::size_t i = 0; i < channel.values.size(); ++i) {
    if (!is_missing(channel.values[i])) {
      valid_t.push_back(time_s[i]);
      valid_v.push_back(channel.values[i]);
    }
  }
  const std::size_t n = valid_t.size();
  if (n == 0) return out;
  // The spacing rule applies to this channel's own valid samples, so a 1 Hz channel blank on
  // the rows of a 100 Hz log sees 1 s spacing and bridges its blank rows.
  const double max_gap =
      (max_gap_s == 0.0 && n >= 2) ? 2.5 * median_spacing_s(valid_t, 1) : max_gap_s;
  const std::optional<double> angle_start =
      channel.interp == Interp::kAngle ? angle_range_start(valid_v) : std::nullopt;

  std::size_t j = 0;  // invariant: valid_t[j] <= t once t >= valid_t[0]
  for (std::size_t k = 0; k < target_s.size(); ++k) {
    const double t = target_s[k];
    if (t < valid_t.front()) continue;
    if (t > valid_t.back()) break;  // no extrapolation; later targets are larger still
    while (j + 1 < n && valid_t[j + 1] <= t) ++j;
    if (t == valid_t[j]) {
      out[k] = valid_v[j];
      continue;
    }
    // Here valid_t[j] < t < valid_t[j + 1].
    const double t0 = valid_t[j];
    const double t1 = valid_t[j + 1];
    if (t1 - t0 > max_gap) continue;
    switch (channel.interp) {
      case Interp::kLinear:
        out[k] = valid_v[j] + (valid_v[j + 1] - valid_v[j]) * ((t - t0) / (t1 - t0));
        break;
      case Interp::kNearest:
        out[k] = (t - t0 <= t1 - t) ? valid_v[j] : valid_v[j + 1];
        break;
      case Interp::kHold:
        out[k] = valid_v[j];
        break;
      case Interp::kAngle:
        out[k] = interpolate_angle(valid_v[j], valid_v[j + 1], (t - t0) / (t1 - t0), angle_start);
        break;
    }
  }
  return out;
}

}  // namespace

Log::Log(std::vector<double> time_s) : time_s_(std::move(time_s)) {
  check_time_axis(time_s_, "Log", 1);
}

Log::Log(std::vector<double> time_s, unsigned jobs) : time_s_(std::move(time_s)) {
  check_time_axis(time_s_, "Log", jobs);
}

void Log::add_channel(std::string name, std::string unit, std::vector<double> values,
                      Interp interp) {
  if (name.empty()) throw std::invalid_argument("add_channel: the channel name is empty");
  if (has(name)) {
    throw std::invalid_argument("add_channel: channel " + single_quoted(name) +
                                " already exists; channel names must be unique");
  }
  if (values.size() != time_s_.size()) {
    throw std::invalid_argument("add_channel: channel " + single_quoted(name) + " has " +
                                std::to_string(values.size()) + " values but the log has " +
                                std::to_string(time_s_.size()) + " time samples");
  }
  channels_.push_back(Channel{std::move(name), std::move(unit), interp, std::move(values)});
}

void Log::declare_channel(std::string name, std::string unit, Interp interp) {
  if (!empty()) {
    throw std::invalid_argument("declare_channel: channel " + single_quoted(name) +
                                " declared after " + std::to_string(size()) +
                                " rows; declare before append_row() or use add_channel()");
  }
  add_channel(std::move(name), std::move(unit), {}, interp);
}

void Log::append_row(double t_s, std::span<const double> values) {
  if (values.size() != channels_.size()) {
    throw std::invalid_argument("append_row at t = " + num(t_s) +
                                " s: " + std::to_string(values.size()) + " values for " +
                                std::to_string(channels_.size()) + " channels");
  }
  if (!std::isfinite(t_s)) {
    throw std::invalid_argument("append_row: time " + num(t_s) + " is not finite");
  }
  if (!empty() && !(t_s > time_s_.back())) {
    throw std::invalid_argument("append_row: time " + num(t_s) + " s is not after the last time " +
                                num(time_s_.back()) + " s; rows must have increasing times");
  }
  time_s_.push_back(t_s);
  for (std::size_t i = 0; i < channels_.size(); ++i) channels_[i].values.push_back(values[i]);
}

void Log::reserve(std::size_t n) {
  time_s_.reserve(n);
  for (Channel& c : channels_) c.values.reserve(n);
}

void Log::clear_rows() noexcept {
  time_s_.clear();
  for (Channel& c : channels_) c.values.clear();
}

bool Log::has(std::string_view name) const noexcept {
  return std::any_of(channels_.begin(), channels_.end(),
                     [name](const Channel& c) { return c.name == name; });
}

const Channel& Log::channel(std::string_view name) const {
  for (const Channel& c : channels_) {
    if (c.name == name) return c;
  }
  std::string known;
  for (const Channel& c : channels_) known += (known.empty() ? "" : ", ") + c.name;
  throw std::out_of_range("no channel " + single_quoted(name) +
                          " in the log; channels are: " + (known.empty() ? "(none)" : known));
}

Channel& Log::channel(std::string_view name) {
  return const_cast<Channel&>(std::as_const(*this).channel(name));
}

std::vector<std::string> Log::channel_names() const {
  std::vector<std::string> names;
  names.reserve(channels_.size());
  for (const Channel& c : channels_) names.push_back(c.name);
  return names;
}

Log Log::resample(const std::vector<double>& time_s, const ResampleOptions& options) const {
  if (!(options.max_gap_s >= 0.0)) {
    throw std::invalid_argument("resample: max_gap_s = " + num(options.max_gap_s) +
                                "; it must be >= 0 (0 = automatic, infinity = never a gap)");
  }
  check_time_axis(time_s, "resample target", 1);
  Log out(time_s);
  out.channels_.reserve(channels_.size());
  for (const Channel& c : channels_) {
    out.channels_.push_back(
        Channel{c.name, c.unit, c.interp, resample_channel(time_s_, c, time_s, options.max_gap_s)});
  }
  return out;
}

Log Log::window(double t_from_s, double t_to_s) const {
  if (std::isnan(t_from_s) || std::isnan(t_to_s) || t_from_s > t_to_s) {
    throw std::invalid_argument("window: [" + num(t_from_s) + ", " + num(t_to_s) +
                                "] s is not an interval; need t_from_s <= t_to_s");
  }
  const auto lo = std::lower_bound(time_s_.begin(), time_s_.end(), t_from_s);
  const auto hi = std::upper_bound(lo, time_s_.end(), t_to_s);
  const auto first = static_cast<std::size_t>(lo - time_s_.begin());
  const auto last = static_cast<std::size_t>(hi - time_s_.begin());
  Log out;
  out.time_s_.assign(lo, hi);
  out.channels_.reserve(channels_.size());
  for (const Channel& c : channels_) {
    if (c.values.size() != time_s_.size()) {
      throw std::invalid_argument("window: channel " + single_quoted(c.name) + " has " +
                                  std::to_string(c.values.size()) + " values but the log has " +
                                  std::to_string(time_s_.size()) + " time samples");
    }
    out.channels_.push_back(
        Channel{c.name, c.unit, c.interp,
                std::vector<double>(c.values.begin() + static_cast<std::ptrdiff_t>(first),
                                    c.values.begin() + static_cast<std::ptrdiff_t>(last))});
  }
  return out;
}

}  // namespace dynpos::core
