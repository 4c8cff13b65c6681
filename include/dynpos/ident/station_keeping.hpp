#pragma once
/// \file
/// Stationkeeping (pure DP) statistics over a window, as thesis tables 3.11–3.22 report them:
/// position spread, heading and wind (circular statistics for directions), mean thrust and
/// energy per thruster and in total.
///
/// Definitions (docs/theory.md, "Stationkeeping"):
/// - position std: the population standard deviation of the north and of the east samples in
///   the window about their own mean [m] (any constant offset of the position, e.g. UTM, drops
///   out);
/// - heading and wind direction: circular mean and standard deviation (core/circular_stats.hpp);
/// - wind speed: mean and population standard deviation of the samples;
/// - mean thrust of a thruster: the time-weighted mean of |T| over the window [N] (a tunnel
///   thruster pushing both ways still works); total = the sum over thrusters;
/// - energy: ∫P dt [J] per thruster and summed; accumulated thrust ∫|T| dt [N·s].
/// A figure whose channel is not logged, or too sparsely (channel_integrals.hpp), is missing;
/// a total is missing when any of its thrusters' figures is.

#include <optional>
#include <string>
#include <vector>

#include "dynpos/ident/channel_integrals.hpp"

namespace dynpos::ident {

/// The channels of one thruster, on the input's time axis; an empty vector = not logged.
struct ThrusterChannels {
  std::string name;
  std::vector<double> thrust_N;
  std::vector<double> power_W;
};

/// The logged channels, SI, NaN = missing sample; an empty vector = not logged.
struct StationKeepingInput {
  std::vector<double> t_s;  ///< strictly increasing
  std::vector<double> north_m, east_m;
  std::vector<double> heading_rad;
  std::vector<double> wind_speed_mps, wind_dir_rad;  ///< direction the wind comes from
  std::vector<ThrusterChannels> thrusters;
  /// How far the log reaches [s] when t_s holds only a window of it (read bounded by the
  /// window); unset: t_s.front() and t_s.back().
  std::optional<double> log_start_s;
  std::optional<double> log_end_s;
};

/// A time window, with a name for tables (e.g. "heading 90").
struct TimeWindow {
  std::string name;
  double t_from_s = 0.0;
  double t_to_s = 0.0;
};

struct MeanStd {
  std::optional<double> mean;
  std::optional<double> std;
};

struct ThrusterSummary {
  std::string name;
  std::optional<double> mean_abs_thrust_N;
  std::optional<double> accumulated_thrust_Ns;
  std::optional<double> energy_J;
};

struct StationKeepingResult {
  TimeWindow window;
  std::optional<double> position_std_north_m;
  std::optional<double> position_std_east_m;
  std::size_t position_samples = 0;
  MeanStd heading_rad;
  MeanStd wind_speed_mps;
  MeanStd wind_dir_rad;
  std::vector<ThrusterSummary> thrusters;
  std::optional<double> total_mean_abs_thrust_N;
  std::optional<double> total_accumulated_thrust_Ns;
  std::optional<double> total_energy_J;
};

/// The statistics of one window. Throws core::InputError when the window is not inside the
/// log or when fewer than `min_position_samples` position samples fall in it (of the request
/// key "from/to"), or when the position is not logged.
StationKeepingResult analyse_station_keeping(const StationKeepingInput& input,
                                             const TimeWindow& window,
                                             const ChannelIntegralOptions& integrals = {},
                                             std::size_t min_position_samples = 10);

/// One window per DP setpoint: the last `duration_s` seconds before each setpoint change (and
/// before the end of the log), named after the setpoint heading ("heading 90"). A hold shorter
/// than `duration_s` gives a window over the whole hold; one shorter than half of `duration_s`
/// (a hold cut off by the end of the log, a transit) gives none. Setpoint channels: SI, NaN =
/// missing (held from the last valid sample).
std::vector<TimeWindow> setpoint_windows(const std::vector<double>& t_s,
                                         const std::vector<double>& setpoint_north_m,
                                         const std::vector<double>& setpoint_east_m,
                                         const std::vector<double>& setpoint_heading_rad,
                                         double duration_s);

}  // namespace dynpos::ident
