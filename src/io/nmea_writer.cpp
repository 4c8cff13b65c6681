#include "dynpos/io/nmea_writer.hpp"

#include <fmt/core.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>

#include "dynpos/core/log.hpp"

namespace dynpos::io {
namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;
constexpr double kMpsToKnot = 3600.0 / 1852.0;
constexpr double kMpsToKmh = 3.6;

void check_talker(std::string_view talker) {
  bool ok = talker.size() == 2;
  for (const char c : talker) ok = ok && ((c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'));
  if (!ok) {
    throw std::invalid_argument(fmt::format("NMEA talker '{}' is not two letters", talker));
  }
}

// A number with `decimals` digits after the point; NaN → empty.
std::string number(double value, int decimals) {
  if (core::is_missing(value)) return {};
  return fmt::format("{:.{}f}", value, decimals);
}

// An angle in degrees wrapped to [0, 360) after rounding to `Decimals`; NaN → empty.
template <int Decimals>
std::string direction_deg(double rad) {
  if (core::is_missing(rad)) return {};
  const double scale = std::pow(10.0, Decimals);
  double deg = std::round(rad * kRadToDeg * scale) / scale;
  deg = std::fmod(deg, 360.0);
  if (deg < 0.0) deg += 360.0;
  if (deg >= 360.0 - 0.5 / scale) deg = 0.0;
  return fmt::format("{:.{}f}", deg, Decimals);
}

// "hhmmss.sss" of the time of day (modulo one day); NaN → empty.
std::string time_field(double utc_s) {
  if (core::is_missing(utc_s)) return {};
  if (!(utc_s >= 0.0) || !std::isfinite(utc_s)) {
    throw std::invalid_argument(fmt::format("NMEA time {} s is negative or not finite", utc_s));
  }
  const auto ms = static_cast<std::int64_t>(std::llround(utc_s * 1000.0)) % 86'400'000;
  const std::int64_t s = ms / 1000;
  return fmt::format("{:02d}{:02d}{:02d}.{:03d}", s / 3600, s / 60 % 60, s % 60, ms % 1000);
}

// Latitude or longitude: the digits of its whole degrees and its hemisphere letters.
struct AngleAxis {
  int degree_digits;
  char positive;
  char negative;
};
constexpr AngleAxis kLatitude{2, 'N', 'S'};
constexpr AngleAxis kLongitude{3, 'E', 'W'};

// Latitude "ddmm.mmmmmmm,N" or longitude "dddmm.mmmmmmm,E" (two fields); NaN → ",".
std::string angle_fields(double rad, const AngleAxis& axis) {
  if (core::is_missing(rad)) return ",";
  const int degree_digits = axis.degree_digits;
  const char positive = axis.positive, negative = axis.negative;
  const double deg = rad * kRadToDeg;
  const double limit = degree_digits == 2 ? 90.0 : 180.0;
  if (!(std::abs(deg) <= limit)) {
    throw std::invalid_argument(fmt::format("NMEA angle {}° is beyond ±{}°", deg, limit));
  }
  // Whole 1e-7 minutes, so the rounding never carries into "60.0000000" minutes.
  constexpr std::int64_t kUnitsPerMinute = 10'000'000;
  const auto units = static_cast<std::int64_t>(std::llround(std::abs(deg) * 60.0 * 1e7));
  const std::int64_t degrees = units / (60 * kUnitsPerMinute);
  const std::int64_t rest = units % (60 * kUnitsPerMinute);
  return fmt::format("{:0{}d}{:02d}.{:07d},{}", degrees, degree_digits, rest / kUnitsPerMinute,
                     rest % kUnitsPerMinute, deg < 0.0 ? negative : positive);
}

// A value and its unit letter (two fields); NaN → ",".
std::string with_unit(double value, int decimals, char unit) {
  if (core::is_missing(value)) return ",";
  return number(value, decimals) + "," + unit;
}

std::string mode_field(char mode) { return mode == '\0' ? std::string{} : std::string(1, mode); }

}  // namespace

std::string nmea_frame(std::string_view body) {
  return fmt::format("${}*{:02X}", body, nmea_checksum(body));
}

std::string format_gga(std::string_view talker, const NmeaGga& g) {
  check_talker(talker);
  if (g.quality < -1 || g.quality > 9) {
    throw std::invalid_argument(fmt::format("GGA fix quality {} is not −1…9", g.quality));
  }
  const std::string satellites =
      core::is_missing(g.satellites) ? std::string{} : fmt::format("{:02.0f}", g.satellites);
  return nmea_frame(
      fmt::format("{}GGA,{},{},{},{},{},{},{},{},{},{}", talker, time_field(g.utc_s),
                  angle_fields(g.lat_rad, kLatitude), angle_fields(g.lon_rad, kLongitude),
                  g.quality < 0 ? std::string{} : std::to_string(g.quality), satellites,
                  number(g.hdop, 2), with_unit(g.altitude_m, 3, 'M'),
                  with_unit(g.geoid_separation_m, 3, 'M'), number(g.age_s, 1), g.station));
}

std::string format_rmc(std::string_view talker, const NmeaRmc& r) {
  check_talker(talker);
  const std::string date =
      r.date ? fmt::format("{:02d}{:02d}{:02d}", r.date->day, r.date->month, r.date->year % 100)
             : std::string{};
  std::string variation = ",";
  if (!core::is_missing(r.magnetic_variation_rad)) {
    const double deg = r.magnetic_variation_rad * kRadToDeg;
    variation = fmt::format("{:.1f},{}", std::abs(deg), deg < 0.0 ? 'W' : 'E');
  }
  return nmea_frame(fmt::format("{}RMC,{},{},{},{},{},{},{},{},{}", talker, time_field(r.utc_s),
                                r.valid ? 'A' : 'V', angle_fields(r.lat_rad, kLatitude),
                                angle_fields(r.lon_rad, kLongitude),
                                number(r.sog_mps * kMpsToKnot, 3), direction_deg<2>(r.cog_rad),
                                date, variation, mode_field(r.mode)));
}

std::string format_vtg(std::string_view talker, const NmeaVtg& v) {
  check_talker(talker);
  const std::string cog = direction_deg<2>(v.cog_rad);
  const std::string cog_m = direction_deg<2>(v.cog_magnetic_rad);
  return nmea_frame(fmt::format("{}VTG,{},{},{},{},{},{},{}", talker, cog, cog.empty() ? "" : "T",
                                cog_m, cog_m.empty() ? "" : "M",
                                with_unit(v.sog_mps * kMpsToKnot, 3, 'N'),
                                with_unit(v.sog_mps * kMpsToKmh, 3, 'K'), mode_field(v.mode)));
}

std::string format_hdt(std::string_view talker, const NmeaHdt& h) {
  check_talker(talker);
  const std::string heading = direction_deg<3>(h.heading_rad);
  return nmea_frame(fmt::format("{}HDT,{},{}", talker, heading, heading.empty() ? "" : "T"));
}

std::string format_rot(std::string_view talker, const NmeaRot& r) {
  check_talker(talker);
  return nmea_frame(fmt::format("{}ROT,{},{}", talker, number(r.rate_rad_s * kRadToDeg * 60.0, 2),
                                r.valid ? 'A' : 'V'));
}

}  // namespace dynpos::io
