#pragma once
/// \file
/// Log: a columnar time series — one time axis and named channels with units.
///
/// Every channel has one value per time sample. A missing value is NaN (see is_missing()):
/// merged logs where a 1 Hz channel is blank between the samples of a 100 Hz log are normal,
/// and missing is never turned into zero. Values are SI (see core/units.hpp) unless the unit
/// string says otherwise.

#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace dynpos::core {

/// The value stored for a missing sample.
inline constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();

/// True when a sample is missing (NaN).
inline bool is_missing(double value) { return std::isnan(value); }

/// The missing samples of a series, counted in pieces on `jobs` threads (0 = every core).
std::size_t missing_count(std::span<const double> values, unsigned jobs);

/// How a channel is interpolated onto another time axis.
enum class Interp {
  kLinear,   ///< continuous signals: linear between the two valid neighbours
  kNearest,  ///< discrete signals: the valid sample nearest in time (a tie takes the earlier)
  kHold,     ///< discrete signals: the last valid sample at or before t (zero-order hold)
  /// angles [rad]: linear along the shorter arc, ψ = ψ₀ + wrap(ψ₁ − ψ₀)·(t − t₀)/(t₁ − t₀) with
  /// wrap to [−π, π), then put back in the channel's range: [0, 2π) when every valid sample is
  /// in [0, 2π], else [−π, π) when every one is in [−π, π], else (an unwrapped series) as is.
  kAngle,
};

/// One named signal: values on the owning Log's time axis.
struct Channel {
  std::string name;
  std::string unit;  ///< unit of `values`, e.g. "m", "rad", "m/s", "1" for dimensionless
  Interp interp = Interp::kLinear;
  std::vector<double> values;  ///< one per time sample; NaN = missing
};

/// Options for Log::resample().
struct ResampleOptions {
  /// Largest spacing [s] between two valid samples of a channel that is still bridged by
  /// interpolation; a target time inside a wider gap gets NaN. 0 = automatic: 2.5 times the
  /// median spacing of that channel's valid samples. Infinity bridges every gap.
  double max_gap_s = 0.0;
};

/// A columnar time series. Time [s] is strictly increasing and finite.
class Log {
 public:
  Log() = default;

  /// A log with the given time axis and no channels.
  /// Throws std::invalid_argument if a time is not finite or not strictly increasing.
  explicit Log(std::vector<double> time_s);
  /// Log(time_s), a long axis checked in pieces on `jobs` threads (0 = every core).
  Log(std::vector<double> time_s, unsigned jobs);

  std::size_t size() const noexcept { return time_s_.size(); }
  bool empty() const noexcept { return time_s_.empty(); }
  const std::vector<double>& time() const noexcept { return time_s_; }

  /// Adds a channel. Throws std::invalid_argument if the name is taken or the length differs.
  void add_channel(std::string name, std::string unit, std::vector<double> values,
                   Interp interp = Interp::kLinear);

  /// Declares a channel with no samples yet, for filling row by row with append_row().
  /// Only allowed while the log has no rows.
  void declare_channel(std::string name, std::string unit, Interp interp = Interp::kLinear);

  /// Appends one sample row; `values` are in channel order (channel_names()).
  /// Throws std::invalid_argument if t is not after the last time or the count is wrong.
  void append_row(double t_s, std::span<const double> values);

  /// Reserves room for n rows in the time axis and every channel.
  void reserve(std::size_t n);

  /// Removes every row; the channels and the reserved room stay (a log written out a block at
  /// a time reuses its memory).
  void clear_rows() noexcept;

  bool has(std::string_view name) const noexcept;
  /// Throws std::out_of_range naming the channel (and the ones there are) if it is absent.
  const Channel& channel(std::string_view name) const;
  Channel& channel(std::string_view name);
  /// Shorthand for channel(name).values.
  const std::vector<double>& values(std::string_view name) const { return channel(name).values; }
  /// Channel names in insertion order.
  std::vector<std::string> channel_names() const;
  const std::vector<Channel>& channels() const noexcept { return channels_; }

  /// The log on another time axis: each channel by its own Interp mode, using only valid
  /// samples; NaN outside the channel's valid range (no extrapolation) and inside gaps wider
  /// than options.max_gap_s. A target time equal to a valid sample's time gets that sample.
  /// Runs in O(N + M) per channel (N rows, M target times).
  /// Throws std::invalid_argument if `time_s` is not finite and strictly increasing, or if
  /// options.max_gap_s is negative or NaN.
  Log resample(const std::vector<double>& time_s, const ResampleOptions& options = {}) const;

  /// The samples with t_from_s <= t <= t_to_s (all channels); empty if none.
  /// Throws std::invalid_argument if t_from_s > t_to_s or either is NaN.
  Log window(double t_from_s, double t_to_s) const;

 private:
  std::vector<double> time_s_;
  std::vector<Channel> channels_;
};

}  // namespace dynpos::core
