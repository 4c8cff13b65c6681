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
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dynpos/core/log.hpp"
#include "dynpos/io/nmea_sentence.hpp"

namespace dynpos::scenario {

/// What the device files hold besides the log's samples (scenario file section
/// [device_files]).
struct DeviceFilesSpec {
  double feedback_rate_hz = 2.0;  ///< [Hz] thruster and order files; divides the log rate
  double order_wiggle_rpm = 3.0;  ///< [rpm] 0…50, half-width of the dither on rpm orders
  double order_wiggle_deg = 1.0;  ///< [deg] 0…10, on rudder orders
  double order_wiggle_pct = 0.5;  ///< [%] 0…10, on lever and force orders
};

/// What a run's files need besides its rows.
struct RunFileContext {
  /// UTC of t = 0, "YYYY-MM-DDTHH:MM:SS[.sss]Z" (ScenarioSpec::start_utc).
  std::string start_utc;
  /// [m] geoid above the WGS84 ellipsoid at the GNSS origin (ScenarioRun::geoid_separation_m).
  double geoid_separation_m = 0.0;
  /// The run's master seed: the orders' dither is drawn from it.
  std::uint64_t seed = 0;
  /// Write the device files too.
  std::optional<DeviceFilesSpec> device_files;
};

/// One NMEA sentence (without CR LF) and the log time [s] of its fix.
struct TimedSentence {
  double t_s = 0.0;
  std::string text;
};

/// The antennas of a trial log: prefixes "gnssK" with lat, lon, height, north and east.
std::vector<std::string> gnss_antennas(const core::Log& log);

/// One antenna's NMEA sentences as a run's rows arrive, block by block: per 1 Hz fix GNGGA,
/// GNRMC, GNVTG and HEHDT, as the virtual receivers send them (docs/log-format.md,
/// "gnssK.nmea"). A fix's speed and course come from its neighbouring fixes, so a fix is sent
/// when the next one arrives, the last one by finish(). The sentences do not depend on how the
/// rows are split into blocks.
class GnssSentenceStream {
 public:
  /// For `antenna` of logs with the channels of `layout`. Throws std::invalid_argument if
  /// context.start_utc has no date, std::out_of_range if a channel of the antenna is missing.
  GnssSentenceStream(const core::Log& layout, const std::string& antenna,
                     const RunFileContext& context);
  /// Takes the next rows (the channels of `layout`); appends the sentences they complete.
  void add(const core::Log& block, std::vector<TimedSentence>& out);
  /// Appends the last fix's sentences.
  void finish(std::vector<TimedSentence>& out);

 private:
  struct Fix {
    double t_s, lat_deg, lon_deg, height_m, north_m, east_m, heading_deg;
  };
  void send(const Fix& fix, const Fix& before, const Fix& after, bool has_track,
            std::vector<TimedSentence>& out) const;

  std::size_t lat_, lon_, height_, north_, east_;
  std::optional<std::size_t> heading_;
  io::UtcDate start_date_;
  double start_time_of_day_s_ = 0.0;
  double geoid_separation_m_ = 0.0;
  std::optional<Fix> before_, pending_;
  double last_heading_deg_ = core::kMissing;
};

/// Writes DIR (created if needed) as described in the file comment, block by block. The dither
/// is drawn from the run's seed: the same run gives the same files, bit for bit, however its
/// rows are split. Nothing appears at the files' paths before commit().
class DeviceFileWriter {
 public:
  /// For logs with the channels of `layout` (the trial logger's). Throws std::runtime_error
  /// if a file cannot be created.
  DeviceFileWriter(const core::Log& layout, const RunFileContext& context,
                   const std::filesystem::path& dir);
  ~DeviceFileWriter();
  DeviceFileWriter(const DeviceFileWriter&) = delete;
  DeviceFileWriter& operator=(const DeviceFileWriter&) = delete;

  /// Writes the files' lines of the next rows.
  void add(const core::Log& block);
  /// Finishes every file and renames it into place.
  void commit();

 private:
  struct Files;
  std::unique_ptr<Files> files_;
};

}  // namespace dynpos::scenario
