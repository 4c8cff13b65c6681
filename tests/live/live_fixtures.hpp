#pragma once
// Fixtures of the live tests, written here: a step-test CSV log with a known FOPDT response, an
// NMEA capture of a vessel holding position (GGA and HDT, 1 Hz), IEC 61162-450 tag blocks, a
// temporary folder, and a session's JSON lines taken apart.

#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace dynpos::live::test {

/// The steps of step_csv(): times [s] and the levels the command steps to.
inline constexpr double kStepTimes[] = {10.0, 40.0, 70.0};

/// "time [s],cmd [1],y [1]" at 10 Hz over [0, duration_s]: cmd 0, then 1, 3, 2 at kStepTimes;
/// y its FOPDT response (K = 2, T = 3 s, dead time 0.5 s) plus ±0.002 of deterministic noise.
/// One string per line, line end included (the header first).
std::vector<std::string> step_csv(double duration_s = 100.0);

/// The NMEA sentence `body` (without '$' and checksum) with both, and CR LF.
std::string nmea_sentence(const std::string& body);
/// A tag block "\\s:GP0001,c:UNIX*hh\\" of `unix_s`; `corrupt` spoils its checksum.
std::string tag_block(long unix_s, bool corrupt = false);

/// A GGA and an HDT per second from 10:00:00 UTC: a vessel moving about a point (position
/// within a metre, heading 90° ± 2°), `seconds` long.
std::vector<std::string> station_capture(int seconds);

/// A folder of its own under the system's temporary folder, removed with the object.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

/// Writes `lines` to `file`.
void write_lines(const std::filesystem::path& file, const std::vector<std::string>& lines);
/// The lines (without '\n') written to a temporary FILE.
std::vector<std::string> read_back(std::FILE* file);

/// A JSON line taken apart: the document before the added keys, and the keys.
struct LiveLine {
  std::string document;  ///< compact, as the offline document's dump()
  std::optional<double> stream_time_s;
  bool final = false;
};
/// Splits a line at its last `,"stream_time_s":`; fails the test on another form.
LiveLine split_live_line(const std::string& line);

}  // namespace dynpos::live::test
