#pragma once
/// \file
/// One NMEA 0183 sentence: "$TTSSS,f1,f2,…*hh" parsed into a typed record.
///
/// The address is a two-letter talker ID (GP, GN, GL, GA, IN, HE, …; any is accepted) and a
/// sentence type. GGA, RMC, VTG, GLL, ZDA, HDT, THS, HDG, ROT and the Kongsberg Seapath
/// proprietary PSXN,20/22/23 are decoded into records in SI units (angles in rad, speeds in m/s,
/// rates in rad/s, time in seconds since 00:00 UTC); other types keep only their address and
/// raw fields. The checksum (XOR of the bytes between '$' and '*', two hex
/// digits) is verified when present. An empty field is missing (NaN), never zero.
/// Rules and error cases are in docs/log-format.md, "NMEA 0183 input".

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "dynpos/core/error.hpp"

namespace dynpos::io {

/// A calendar date (proleptic Gregorian, UTC).
struct UtcDate {
  int year = 1970;  ///< four digits
  int month = 1;    ///< 1…12
  int day = 1;      ///< 1…31
  friend bool operator==(const UtcDate&, const UtcDate&) = default;
};

/// "YYYY-MM-DD".
std::string to_iso(const UtcDate& date);
/// The date `days` days after `date` (negative: before).
UtcDate add_days(const UtcDate& date, long days);
/// Days from 1970-01-01 to `date`.
long days_since_epoch(const UtcDate& date);
/// True if the date exists (month 1…12, day within the month, leap years included).
bool is_valid(const UtcDate& date);

/// GGA, global positioning fix data: time, position, fix quality.
struct NmeaGga {
  double utc_s = 0.0;    ///< [s] since 00:00 UTC, NaN if the field is empty
  double lat_rad = 0.0;  ///< [rad] + north, NaN if empty
  double lon_rad = 0.0;  ///< [rad] + east, NaN if empty
  int quality = 0;       ///< fix quality: 0 no fix, 1 GPS, 2 DGPS, 4 RTK fixed, 5 RTK float, 6 dead
                         ///< reckoning, …; −1 if the field is empty
  double satellites = 0.0;          ///< satellites in use, NaN if empty
  double hdop = 0.0;                ///< horizontal dilution of precision [1], NaN if empty
  double altitude_m = 0.0;          ///< [m] antenna height above the geoid (mean sea level)
  double geoid_separation_m = 0.0;  ///< [m] geoid above the WGS84 ellipsoid, NaN if empty
  double age_s = 0.0;               ///< [s] age of differential corrections, NaN if empty
  std::string station;              ///< differential reference station ID, may be empty
};

/// RMC, recommended minimum data: time, date, validity, position, speed and course.
struct NmeaRmc {
  double utc_s = 0.0;                   ///< [s] since 00:00 UTC, NaN if empty
  bool valid = false;                   ///< status 'A' (valid) vs 'V' (void)
  double lat_rad = 0.0;                 ///< [rad], NaN if empty
  double lon_rad = 0.0;                 ///< [rad], NaN if empty
  double sog_mps = 0.0;                 ///< speed over ground [m/s] (logged in knots), NaN if empty
  double cog_rad = 0.0;                 ///< course over ground, true [rad], NaN if empty
  std::optional<UtcDate> date;          ///< ddmmyy; yy < 80 → 20yy, else 19yy
  double magnetic_variation_rad = 0.0;  ///< [rad] + east, NaN if empty
  char mode = '\0';  ///< NMEA 2.3 mode indicator (A, D, E, M, S, N, …), '\0' if absent
};

/// VTG, course and speed over ground.
struct NmeaVtg {
  double cog_rad = 0.0;           ///< course over ground, true [rad], NaN if empty
  double cog_magnetic_rad = 0.0;  ///< magnetic [rad], NaN if empty
  double sog_mps =
      0.0;           ///< [m/s] from the km/h field, else from the knots field; NaN if both empty
  char mode = '\0';  ///< mode indicator, '\0' if absent; 'N' = data not valid
};

/// HDT, true heading (gyro compass or GNSS compass). It carries no time.
struct NmeaHdt {
  double heading_rad = 0.0;  ///< [rad] clockwise from true north, NaN if empty
};

/// ROT, rate of turn. It carries no time.
struct NmeaRot {
  double rate_rad_s = 0.0;  ///< [rad/s] + bow to starboard (logged in deg/min), NaN if empty
  bool valid = false;       ///< status 'A'
};

/// GLL, geographic position with time.
struct NmeaGll {
  double lat_rad = 0.0;  ///< [rad], NaN if empty
  double lon_rad = 0.0;  ///< [rad], NaN if empty
  double utc_s = 0.0;    ///< [s] since 00:00 UTC, NaN if empty
  bool valid = false;    ///< status 'A'
};

/// ZDA, UTC time and date.
struct NmeaZda {
  double utc_s = 0.0;           ///< [s] since 00:00 UTC, NaN if empty
  std::optional<UtcDate> date;  ///< day, month, four-digit year; absent if any is empty
};

/// THS, true heading with a mode. It carries no time.
struct NmeaThs {
  double heading_rad = 0.0;  ///< [rad] clockwise from true north, NaN if empty
  char mode = '\0';          ///< A autonomous, E estimated, M manual, S simulator, V not valid
};

/// HDG, magnetic sensor heading with deviation and variation. It carries no time.
struct NmeaHdg {
  double sensor_heading_rad = 0.0;  ///< [rad] as the magnetic sensor reads it, NaN if empty
  double deviation_rad = 0.0;       ///< [rad] + east, NaN if empty
  double variation_rad = 0.0;       ///< [rad] + east, NaN if empty
};

/// PSXN,20: Kongsberg Seapath quality flags, each 0 normal, 1 reduced, 2 invalid (−1 if empty).
struct NmeaPsxnQuality {
  int horizontal = -1, height = -1, heading = -1, roll_pitch = -1;
};

/// PSXN,22: Kongsberg Seapath gyro calibration.
struct NmeaPsxnGyro {
  double calibration_rad = 0.0;  ///< [rad] gyro calibration since start-up, NaN if empty
  double offset_rad = 0.0;       ///< [rad] short-term gyro offset, NaN if empty
};

/// PSXN,23: Kongsberg Seapath attitude, Seapath 200/320 manual conventions. It carries no time.
struct NmeaPsxnAttitude {
  double roll_rad = 0.0;     ///< [rad] + port side up (= starboard down), NaN if empty
  double pitch_rad = 0.0;    ///< [rad] + bow up, NaN if empty
  double heading_rad = 0.0;  ///< [rad] true, clockwise from north, NaN if empty
  double heave_m = 0.0;      ///< [m] + down, NaN if empty
};

/// A sentence of a type this module does not decode (GSV, GSA, other proprietary, …).
struct NmeaOther {};

/// One parsed sentence.
struct NmeaSentence {
  std::string talker;               ///< "GP", "GN", "HE", …; "P" for proprietary ($PXXXX)
  std::string type;                 ///< "GGA", "RMC", …
  std::vector<std::string> fields;  ///< the raw fields after the address
  bool has_checksum = false;
  std::variant<NmeaOther, NmeaGga, NmeaRmc, NmeaVtg, NmeaHdt, NmeaRot, NmeaGll, NmeaZda, NmeaThs,
               NmeaHdg, NmeaPsxnQuality, NmeaPsxnGyro, NmeaPsxnAttitude>
      data;
};

/// How strictly parse_nmea_sentence() takes field counts.
struct NmeaParseOptions {
  /// false: only the counts NMEA 0183 2.0–4.1 uses for the type. true: any count that reaches
  /// the last field the record needs; missing trailing fields are empty, extra ones ignored
  /// (what many receivers write in practice).
  bool lenient_field_count = false;
};

/// XOR of all bytes of `body` (the text between '$' and '*').
std::uint8_t nmea_checksum(std::string_view body);

/// Parses one line ("$…", trailing CR/LF and spaces allowed). Throws core::InputError with
/// `where` (file, line) completed by the field number (1 = first field after the address) and
/// "TYPE.field" name for: a line not starting with '$', a malformed address, a bad or
/// malformed checksum, a field count that no NMEA version uses for a decoded type, text in a
/// number, a bad hemisphere, unit letter or status, an impossible time, angle or date.
NmeaSentence parse_nmea_sentence(std::string_view line, const core::InputLocation& where = {},
                                 const NmeaParseOptions& options = {});

}  // namespace dynpos::io
