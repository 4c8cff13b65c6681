#pragma once
/// \file
/// The virtual trial's logs as real loggers write them: one file per device, each at its own
/// rate with its own kind of time stamp, a serial capture that starts and ends mid-sentence, and
/// orders that wiggle. Analyses of these files must give what the clean log.csv gives
/// (docs/virtual-gunnerus.md, "Device files").
///
/// DIR/devices/ holds
/// - gnssK.nmea: each antenna's sentences (as DIR/gnssK.nmea) behind a logger time stamp
///   "YYYY-MM-DDTHH:MM:SS.mmmZ " (the fix time, UTC); the first line lacks its first
///   characters and the last line its end, as a capture started and stopped at random;
/// - mru.csv: MRU 1 at its sample rate: roll, pitch, angular rates and accelerations, time as
///   "YYYY-MM-DD HH:MM:SS.mmm+00:00";
/// - thrusters.csv: shaft speed, thrust, power and rudder angle feedback at feedback_rate_hz,
///   time as integer milliseconds since 1970-01-01 UTC;
/// - orders.csv: lever, rpm and rudder orders at feedback_rate_hz with a uniform dither of
///   ± order_wiggle_* on every sample (a held order is never logged clean), time as two
///   columns: whole seconds since 1970-01-01 UTC and nanoseconds.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "dynpos/core/log.hpp"

namespace dynpos::scenario {

struct ScenarioRun;

/// What the device files hold besides the log's samples (scenario file section
/// [device_files]).
struct DeviceFilesSpec {
  double feedback_rate_hz = 2.0;  ///< [Hz] thruster and order files; divides the log rate
  double order_wiggle_rpm = 3.0;  ///< [rpm] 0…50, half-width of the dither on rpm orders
  double order_wiggle_deg = 1.0;  ///< [deg] 0…10, on rudder orders
  double order_wiggle_pct = 0.5;  ///< [%] 0…10, on lever and force orders
};

/// One NMEA sentence (without CR LF) and the log time [s] of its fix.
struct TimedSentence {
  double t_s = 0.0;
  std::string text;
};

/// The antennas of a trial log: prefixes "gnssK" with lat, lon, height, north and east.
std::vector<std::string> gnss_antennas(const core::Log& log);

/// Per 1 Hz fix of `antenna`: GNGGA, GNRMC, GNVTG and HEHDT, as the virtual receivers send
/// them (docs/log-format.md, "gnssK.nmea").
std::vector<TimedSentence> gnss_sentences(const ScenarioRun& run, const std::string& antenna);

/// Writes DIR (created if needed) as described in the file comment. The dither is drawn from
/// the run's seed: the same run gives the same files, bit for bit.
void write_device_files(const ScenarioRun& run, const DeviceFilesSpec& spec,
                        const std::filesystem::path& dir);

}  // namespace dynpos::scenario
