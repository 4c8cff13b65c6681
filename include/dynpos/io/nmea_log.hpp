#pragma once
/// \file
/// A raw NMEA 0183 capture (what a logger or a serial terminal records) read as a log for any
/// analysis: sentences mapped to roles, one time axis, every unusable line skipped and counted.
///
/// Rules, in brief (the full mapping and examples are in docs/log-format.md, "NMEA captures"):
/// - roles: lat/lon from GGA (else RMC, else GLL), height from GGA (altitude + geoid
///   separation), heading from HDT (else THS, PSXN,23, HDG), roll/pitch/down (heave) from
///   PSXN,23, r from ROT; for each role the first source in that order that the file has;
/// - time: a logger time stamp before the '$' when the first used sentence has one, else the
///   sentence UTC (GGA, RMC, GLL, ZDA) with untimed sentences at the last sentence time and the
///   date from ZDA or RMC; t = 0 s at the first sample, its instant in `origin`;
/// - a sentence UTC before the latest one (a second receiver's clock, a reset), unless more
///   than 12 h before (midnight), is skipped as "time back" with the untimed sentences of its
///   epoch: two clocks are never sorted into one;
/// - lines end at '\n', "\r\n" or a lone '\r'; a UTF-8 byte order mark at the start is dropped;
/// - a line that cannot be used is skipped and counted by kind in FileReport::skipped; a
///   benign defect is counted in FileReport::accepted; strict reading makes any skipped line an
///   error.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "dynpos/core/log.hpp"
#include "dynpos/io/input_report.hpp"

namespace dynpos::io {

/// The longest line of a capture that is read as a sentence [bytes]; a longer one (binary data
/// of another protocol on the same port) is skipped and counted as "too long". An NMEA sentence
/// has at most 82 characters; a logger stamp and padding leave the rest.
inline constexpr std::size_t kMaxNmeaLineBytes = std::size_t{64} << 10;
/// The most bytes without a line end before a capture is not text: an error naming the line.
inline constexpr std::size_t kMaxNmeaJunkBytes = std::size_t{16} << 20;
/// A file whose first 100,000 lines, or first 16 MiB, hold no valid NMEA sentence (checksum,
/// address and fields right, of any type) is not an NMEA capture: an error naming the line,
/// not a read to the end of a file that may never end (/dev/urandom).
inline constexpr std::size_t kMaxNmeaLinesWithoutSentence = 100'000;
inline constexpr std::uint64_t kMaxNmeaBytesWithoutSentence = std::uint64_t{16} << 20;

/// Options of read_nmea_log().
struct NmeaLogOptions {
  /// Channel names become PREFIX.ROLE when not empty (e.g. "gnss2" → gnss2.lat, gnss2.lon,
  /// gnss2.height), for a second receiver read beside the main log.
  std::string prefix;
  /// Keeps only the channels (named as in the log, prefix included) it accepts; empty: all.
  std::function<bool(const std::string& channel)> wanted;
  /// Any skipped line throws core::InputError naming file:line and the kind.
  bool strict = false;
};

/// An NMEA 0183 capture as a log.
struct NmeaLog {
  /// time [s] from the first sample; channels lat, lon [rad], height [m], heading, roll,
  /// pitch [rad], down [m], r [rad/s], each only when the capture has it; NaN where a sentence
  /// did not give the role at that time.
  core::Log log;
  /// format "nmea", time_format, records = sentences used, skipped and accepted lines by kind,
  /// notes on how the sentences were read; `path` is the file as given.
  FileReport report;
  std::optional<std::string> origin;      ///< UTC of t = 0 s, ISO 8601; absent without a date
  std::optional<std::int64_t> origin_ns;  ///< the same instant [ns since 1970-01-01 UTC]
};

/// Reads an NMEA capture. Throws core::InputError if the file cannot be read, has no valid
/// sentence in its first kMaxNmeaLinesWithoutSentence lines or kMaxNmeaBytesWithoutSentence
/// bytes ("not an NMEA capture"), holds no sentence giving any role (the message counts what it
/// found by kind), or, when strict, at the first skipped line.
NmeaLog read_nmea_log(const std::filesystem::path& file, const NmeaLogOptions& options = {});

/// True when more than half of the first 200 non-blank lines hold an NMEA sentence ('$' or
/// '!', an address of letters and digits, a comma), with or without text before it.
bool looks_like_nmea(const std::filesystem::path& file);

}  // namespace dynpos::io
