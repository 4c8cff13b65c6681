#pragma once
/// \file
/// InputReport: what was read to make one analysis log — each file, its format and time
/// stamps, the lines it skipped by kind, where each role came from and at what rate, and the
/// absolute time of t = 0. Every analysis report carries one, so a user sees what the tool
/// made of a real logger's files (`input` in the JSON, "input:" lines in the text).

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace dynpos::io {

/// Lines counted by kind, e.g. {"bad checksum": 3, "truncated": 2}. Kinds are short
/// lower-case phrases; docs/log-format.md lists the ones the readers use.
class LineCounts {
 public:
  void add(std::string_view kind, std::size_t n = 1);
  std::size_t total() const noexcept;
  std::size_t count(std::string_view kind) const noexcept;
  bool empty() const noexcept { return by_kind_.empty(); }
  const std::map<std::string, std::size_t, std::less<>>& by_kind() const noexcept {
    return by_kind_;
  }

 private:
  std::map<std::string, std::size_t, std::less<>> by_kind_;
};

/// One file read for the log.
struct FileReport {
  std::string path;                ///< as the user gave it
  std::string format;              ///< "csv", "nmea" or "mcap"
  std::string topic;               ///< a bag's topic this entry is about; empty for other files
  std::string time_format;         ///< how its time stamps were read, e.g. "seconds", "iso8601"
  double clock_offset_s = 0.0;     ///< added to this file's times to put it on the log's clock
  std::size_t records = 0;         ///< data rows or sentences used
  LineCounts skipped;              ///< lines not used, by kind (never fatal unless strict)
  LineCounts accepted;             ///< lines used despite a benign defect, e.g. "no checksum"
  std::vector<std::string> notes;  ///< e.g. how an exporter's time-stamp bug was read
};

/// Where one role of the log came from.
struct RoleOrigin {
  std::string role;
  std::string file;               ///< the FileReport::path it was read from
  std::optional<double> rate_hz;  ///< median rate of its valid samples; absent with < 2
  std::string topic = {};         ///< and its FileReport::topic (a bag's), else empty
};

/// Everything read to make one log.
struct InputReport {
  std::vector<FileReport> files;  ///< the main log first
  std::vector<RoleOrigin> roles;  ///< in the log's channel order
  /// Absolute time of t = 0 s (the first sample of the main log), ISO 8601; absent when the
  /// time stamps are relative. Local times without a zone carry no suffix and say so in
  /// origin_zone.
  std::optional<std::string> origin;
  std::string origin_zone;  ///< "UTC", "+02:00", "local (no zone in the file)" or ""

  /// The report's file entry for `path`, or nullptr.
  const FileReport* file(std::string_view path) const noexcept;

  /// Appends the files and roles of `other` (read for the same analysis, e.g. a second
  /// receiver's file); the origin stays this report's.
  void append(InputReport other);
};

/// {files: [{path, topic (a bag's only), format, time_format, clock_offset_s, records, skipped:
/// {kind: n}, accepted: {kind: n}, notes: [...]}], roles: [{role, file, topic (a bag's only),
/// rate_hz}], origin, origin_zone}.
nlohmann::json to_json(const InputReport& report);

/// "input: FILE (format, time stamps: ..., N records, skipped: 3 bad checksum, ...)" lines, one
/// per file, then the origin line when known; each ends in '\n'.
std::string to_text(const InputReport& report);

}  // namespace dynpos::io
