#pragma once
/// \file
/// The options of `leverarm gnss` as a command line gives them, as text: files per antenna as
/// gnssK=FILE, gains and arms as X,Y,Z, the UTC of the log's start. Parsed into the typed
/// request fields, each error naming the field's request key with an example in its hint.

#include <string>
#include <vector>

#include "dynpos/analysis/leverarm_gnss.hpp"

namespace dynpos::analysis {

/// The text options of `leverarm gnss`; each field's name is its request key.
struct LeverarmGnssText {
  std::vector<std::string> gnss_log;  ///< gnssK=FILE.csv each
  std::vector<std::string> nmea;      ///< gnssK=FILE.nmea each
  std::string utc_at_zero;            ///< HH:MM:SS[.sss] or YYYY-MM-DDTHH:MM:SS[.sss]Z; "": unset
  std::vector<std::string> init;      ///< gnssK=X,Y,Z each: an observer's initial arm [m]
  /// X,Y,Z each; "": the request's value is kept.
  std::string w1, w2, gamma, L, init_p0, imu_arm;
};

/// Sets the fields of `request` that `text` gives: gnss_log and nmea become the files given,
/// init gains the arms given, utc_at_zero and the X,Y,Z fields are set when their text is not
/// empty. option_error(key) for a NAME=FILE or gnssK=X,Y,Z without its '=' or a side, a time
/// that is not UTC (parse_utc_at_zero) or a vector that is not three numbers (parse_vec3).
void parse_text(const LeverarmGnssText& text, LeverarmGnssRequest& request);

}  // namespace dynpos::analysis
