#pragma once
/// \file
/// NMEA 0183 GNSS logs: a file of sentences (GGA, RMC, VTG, HDT, ROT) read into a core::Log
/// with one row per fix epoch, SI units, NaN for what the sentences do not give.
///
/// Rules (docs/log-format.md, "NMEA 0183 input"):
/// - An epoch is a UTC time of a timed sentence (GGA, RMC). Timed sentences with the same time
///   form one row. VTG, HDT and ROT carry no time: they belong to the epoch of the last timed
///   sentence before them (the first of each type per epoch is used; later ones are skipped);
///   before the first timed sentence they are skipped.
/// - Position comes from GGA only (it carries height and fix quality); fix quality 0 makes the
///   row's position missing. Height is ellipsoidal: altitude + geoid separation (missing when
///   the separation field is empty). SOG and COG come from VTG, else from a valid RMC.
/// - One talker per sentence type, the first one seen (GNGGA, not also GPGGA; HEHDT, not also
///   INHDT); sentences of other talkers are skipped and counted.
/// - A time earlier than the previous epoch by more than 12 h is a midnight rollover (the next
///   day); by less it is an error. The date of the first RMC gives `date`.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

#include "dynpos/core/log.hpp"
#include "dynpos/io/nmea_sentence.hpp"

namespace dynpos::io {

/// A GNSS log read from NMEA 0183 sentences.
struct NmeaGnssLog {
  /// time [s] = UTC seconds since 00:00 of `date` (continues past 86400 after midnight);
  /// channels PREFIX.lat, PREFIX.lon [rad], PREFIX.height [m, ellipsoidal = GGA altitude + geoid
  /// separation], PREFIX.quality, PREFIX.satellites, PREFIX.hdop [1]; when present heading [rad]
  /// (HDT), PREFIX.sog [m/s], PREFIX.cog [rad] (VTG or RMC), rate_of_turn [rad/s] (ROT).
  /// Missing = NaN.
  core::Log log;
  std::string date;  ///< "YYYY-MM-DD" of time 0, from the first RMC; empty if there is none
  std::size_t sentences = 0;  ///< sentences read (blank lines are not counted)
  std::size_t skipped = 0;    ///< sentences not used: other types, other talkers, duplicates
};

/// Reads an NMEA 0183 file (one sentence a line; LF, CR LF or a lone CR; a UTF-8 byte order
/// mark at the start dropped). Throws core::InputError naming
/// file, line and field (with a hint) for a malformed sentence, a bad checksum, a time going
/// backwards, an RMC date that contradicts the times, an empty file or a file without GGA.
NmeaGnssLog read_nmea_gnss(const std::filesystem::path& file, const std::string& prefix);

/// A UTC instant as written in scenario files and logs.
struct UtcTimestamp {
  std::optional<UtcDate> date;  ///< absent for a bare time of day
  double time_of_day_s = 0.0;   ///< [s] since 00:00 UTC, in [0, 86400)
};

/// "HH:MM:SS[.sss]" or "YYYY-MM-DDTHH:MM:SS[.sss]Z" → date (if given) and time of day.
/// Throws core::InputError (column_name "time") with the expected form if the text is not one
/// of these or names an impossible date or time.
UtcTimestamp parse_utc_timestamp(const std::string& text);

/// "HH:MM:SS[.sss]" or "YYYY-MM-DDTHH:MM:SS[.sss]Z" → seconds since 00:00 UTC.
double parse_utc_time_of_day(const std::string& text);

}  // namespace dynpos::io
