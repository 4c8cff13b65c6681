#include "dynpos/io/nmea_sentence.hpp"

#include <fmt/core.h>

#include <charconv>
#include <cmath>
#include <numbers>

#include "dynpos/core/log.hpp"
#include "text_util.hpp"

namespace dynpos::io {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;
constexpr double kKnotToMps = 1852.0 / 3600.0;
constexpr double kKmhToMps = 1.0 / 3.6;

// A latitude or longitude field: its name, largest value and hemisphere letters.
struct AngleField {
  std::string_view name;
  int max_deg;
  char positive;
  char negative;
};
constexpr AngleField kLatitude{"latitude", 90, 'N', 'S'};
constexpr AngleField kLongitude{"longitude", 180, 'E', 'W'};

// Reads typed values from the fields of one sentence; every error names the field.
class Fields {
 public:
  Fields(const std::vector<std::string>& fields, const core::InputLocation& where, std::string type)
      : fields_(fields), where_(where), type_(std::move(type)) {}

  // The location of field i, named `name`, for an error in it.
  core::InputLocation where(std::size_t i, std::string_view name) const {
    core::InputLocation at = where_;
    at.column = i + 1;
    at.column_name = type_ + "." + std::string(name);
    return at;
  }

  const std::string& text(std::size_t i) const { return fields_[i]; }
  bool empty(std::size_t i) const { return fields_[i].empty(); }

  // A plain decimal number ("-12.5"); empty → NaN.
  double number(std::size_t i, const std::string& name) const {
    const std::string& s = fields_[i];
    if (s.empty()) return core::kMissing;
    bool digit = false;
    for (std::size_t k = 0; k < s.size(); ++k) {
      const char c = s[k];
      if (c >= '0' && c <= '9') {
        digit = true;
      } else if (!(c == '.' || (c == '-' && k == 0))) {
        digit = false;
        break;
      }
    }
    double value = 0.0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
    if (!digit || ec != std::errc() || end != s.data() + s.size()) {
      throw core::InputError(
          where(i, name), fmt::format("'{}' is not a number", s),
          "NMEA numeric fields hold digits, an optional '-' and '.'; leave a field empty when "
          "there is no value");
    }
    return value;
  }

  // A heading [deg] in [0, 360) → rad; empty → NaN.
  double heading(std::size_t i) const {
    const double deg = number(i, "heading");
    if (deg < 0.0 || deg >= 360.0) {
      throw core::InputError(where(i, "heading"),
                             fmt::format("'{}' is not in [0, 360) degrees", fields_[i]),
                             "a heading is 0 (north) to 359.99… degrees, clockwise");
    }
    return deg * kDegToRad;
  }

  // One of the letters in `allowed`, or '\0' if the field is empty.
  char letter(std::size_t i, const std::string& name, std::string_view allowed) const {
    const std::string& s = fields_[i];
    if (s.empty()) return '\0';
    if (s.size() != 1 || allowed.find(s[0]) == std::string_view::npos) {
      throw core::InputError(where(i, name),
                             fmt::format("'{}' is not one of the letters {}", s, allowed),
                             "check the sentence against the NMEA 0183 field order");
    }
    return s[0];
  }

  // "hhmmss[.sss]" → seconds since 00:00; empty → NaN.
  double time_of_day(std::size_t i) const {
    const std::string& s = fields_[i];
    if (s.empty()) return core::kMissing;
    const auto bad = [&] {
      throw core::InputError(where(i, "time"),
                             fmt::format("'{}' is not a UTC time hhmmss[.sss]", s),
                             "hours 00-23, minutes 00-59, seconds 00-60");
    };
    if (s.size() < 6) bad();
    for (std::size_t k = 0; k < 6; ++k) {
      if (s[k] < '0' || s[k] > '9') bad();
    }
    const int hh = (s[0] - '0') * 10 + (s[1] - '0');
    const int mm = (s[2] - '0') * 10 + (s[3] - '0');
    double ss = (s[4] - '0') * 10 + (s[5] - '0');
    if (s.size() > 6) {
      if (s[6] != '.') bad();
      double fraction = 0.0, scale = 0.1;
      for (std::size_t k = 7; k < s.size(); ++k, scale /= 10.0) {
        if (s[k] < '0' || s[k] > '9') bad();
        fraction += (s[k] - '0') * scale;
      }
      ss += fraction;
    }
    if (hh > 23 || mm > 59 || ss >= 61.0) bad();
    return hh * 3600.0 + mm * 60.0 + ss;
  }

  // "(d)ddmm.mmmm" with hemisphere letter at i + 1 → rad; empty → NaN.
  double angle(std::size_t i, const AngleField& field) const {
    const std::string& s = fields_[i];
    if (s.empty()) return core::kMissing;
    const std::string name(field.name);
    const int max_deg = field.max_deg;
    const char positive = field.positive, negative = field.negative;
    const auto bad = [&](const std::string& problem) {
      throw core::InputError(where(i, name), problem,
                             fmt::format("write the {} as {}mm.mmmm (degrees and decimal minutes)",
                                         name, max_deg > 90 ? "ddd" : "dd"));
    };
    const std::size_t dot = s.find('.');
    const std::string whole = s.substr(0, dot);
    if (whole.size() < 3 || whole.size() > 5) bad(fmt::format("'{}' is not ddmm.mmmm", s));
    for (const char c : whole) {
      if (c < '0' || c > '9') bad(fmt::format("'{}' is not a number", s));
    }
    double fraction = 0.0, scale = 0.1;
    if (dot != std::string::npos) {
      for (std::size_t k = dot + 1; k < s.size(); ++k, scale /= 10.0) {
        if (s[k] < '0' || s[k] > '9') bad(fmt::format("'{}' is not a number", s));
        fraction += (s[k] - '0') * scale;
      }
    }
    const long integer = std::stol(whole);
    const long degrees = integer / 100;
    const double minutes = static_cast<double>(integer % 100) + fraction;
    if (minutes >= 60.0) bad(fmt::format("'{}' has {} minutes (at most 59.999…)", s, minutes));
    const double deg = static_cast<double>(degrees) + minutes / 60.0;
    if (deg > max_deg) bad(fmt::format("'{}' is beyond {} degrees", s, max_deg));
    const char hemisphere = letter(i + 1, name + "_hemisphere", std::string{positive, negative});
    if (hemisphere == '\0') {
      throw core::InputError(where(i + 1, name + "_hemisphere"), "the hemisphere letter is missing",
                             fmt::format("give {} or {} after the {}", positive, negative, name));
    }
    return (hemisphere == negative ? -deg : deg) * kDegToRad;
  }

  // "ddmmyy" → date; empty → nullopt.
  std::optional<UtcDate> date(std::size_t i) const {
    const std::string& s = fields_[i];
    if (s.empty()) return std::nullopt;
    bool digits = s.size() == 6;
    for (const char c : s) digits = digits && c >= '0' && c <= '9';
    UtcDate d;
    if (digits) {
      d.day = (s[0] - '0') * 10 + (s[1] - '0');
      d.month = (s[2] - '0') * 10 + (s[3] - '0');
      const int yy = (s[4] - '0') * 10 + (s[5] - '0');
      d.year = yy < 80 ? 2000 + yy : 1900 + yy;
    }
    if (!digits || !is_valid(d)) {
      throw core::InputError(where(i, "date"), fmt::format("'{}' is not a date ddmmyy", s),
                             "day 01-31, month 01-12, two-digit year (80-99: 19yy, else 20yy)");
    }
    return d;
  }

 private:
  const std::vector<std::string>& fields_;
  core::InputLocation where_;
  std::string type_;
};

// Checks the field count against the counts NMEA versions use (`allowed`, ascending). Lenient:
// any count reaching `needed` fields passes, padded with empty fields to the next allowed count
// or cut to the largest.
void check_count(const Fields& f, std::vector<std::string>& fields, const std::string& type,
                 std::initializer_list<std::size_t> allowed, std::size_t needed, bool lenient) {
  if (lenient && fields.size() >= needed) {
    std::size_t target = *(allowed.end() - 1);
    for (const std::size_t n : allowed) {
      if (n >= fields.size()) {
        target = n;
        break;
      }
    }
    fields.resize(target);
    return;
  }
  for (const std::size_t n : allowed) {
    if (fields.size() == n) return;
  }
  std::vector<std::string> names;
  for (const std::size_t n : allowed) names.push_back(std::to_string(n));
  throw core::InputError(
      f.where(fields.empty() ? 0 : fields.size() - 1, "field_count"),
      fmt::format("{} has {} fields after the address", type, fields.size()),
      fmt::format("a {} sentence has {} fields (NMEA 0183 versions 2.0-4.1); the line may be "
                  "cut off or two sentences may be joined",
                  type, detail::join(names, " or ")));
}

NmeaGga parse_gga(const Fields& f) {
  NmeaGga g;
  g.utc_s = f.time_of_day(0);
  g.lat_rad = f.angle(1, kLatitude);
  g.lon_rad = f.angle(3, kLongitude);
  const double quality = f.number(5, "quality");
  if (!core::is_missing(quality) &&
      (quality != std::floor(quality) || quality < 0.0 || quality > 9.0)) {
    throw core::InputError(f.where(5, "quality"),
                           fmt::format("fix quality '{}' is not a digit 0-9", f.text(5)),
                           "0 no fix, 1 GPS, 2 DGPS, 4 RTK fixed, 5 RTK float, 6 dead reckoning");
  }
  g.quality = core::is_missing(quality) ? -1 : static_cast<int>(quality);
  g.satellites = f.number(6, "satellites");
  g.hdop = f.number(7, "hdop");
  g.altitude_m = f.number(8, "altitude");
  if (!f.empty(8)) f.letter(9, "altitude_unit", "M");
  g.geoid_separation_m = f.number(10, "geoid_separation");
  if (!f.empty(10)) f.letter(11, "geoid_separation_unit", "M");
  g.age_s = f.number(12, "age");
  g.station = f.text(13);
  return g;
}

NmeaRmc parse_rmc(const Fields& f, std::size_t count) {
  NmeaRmc r;
  r.utc_s = f.time_of_day(0);
  r.valid = f.letter(1, "status", "AV") == 'A';
  r.lat_rad = f.angle(2, kLatitude);
  r.lon_rad = f.angle(4, kLongitude);
  r.sog_mps = f.number(6, "sog") * kKnotToMps;
  r.cog_rad = f.number(7, "cog") * kDegToRad;
  r.date = f.date(8);
  const double variation = f.number(9, "magnetic_variation");
  const char direction = f.letter(10, "magnetic_variation_direction", "EW");
  r.magnetic_variation_rad = (direction == 'W' ? -variation : variation) * kDegToRad;
  if (count >= 12) r.mode = f.letter(11, "mode", "ADEFMNPRS");
  return r;
}

NmeaVtg parse_vtg(const Fields& f, std::size_t count) {
  NmeaVtg v;
  v.cog_rad = f.number(0, "cog") * kDegToRad;
  if (!f.empty(0)) f.letter(1, "cog_reference", "T");
  v.cog_magnetic_rad = f.number(2, "cog_magnetic") * kDegToRad;
  if (!f.empty(2)) f.letter(3, "cog_magnetic_reference", "M");
  const double knots = f.number(4, "sog_knots");
  if (!f.empty(4)) f.letter(5, "sog_knots_unit", "N");
  const double kmh = f.number(6, "sog_kmh");
  if (!f.empty(6)) f.letter(7, "sog_kmh_unit", "K");
  v.sog_mps = core::is_missing(kmh) ? knots * kKnotToMps : kmh * kKmhToMps;
  if (count >= 9) v.mode = f.letter(8, "mode", "ADEFMNPRS");
  return v;
}

NmeaGll parse_gll(const Fields& f) {
  NmeaGll g;
  g.lat_rad = f.angle(0, kLatitude);
  g.lon_rad = f.angle(2, kLongitude);
  g.utc_s = f.time_of_day(4);
  g.valid = f.letter(5, "status", "AV") == 'A';
  return g;
}

NmeaZda parse_zda(const Fields& f) {
  NmeaZda z;
  z.utc_s = f.time_of_day(0);
  const double day = f.number(1, "day"), month = f.number(2, "month"), year = f.number(3, "year");
  if (core::is_missing(day) || core::is_missing(month) || core::is_missing(year)) return z;
  // Years 1970-2199: instants any two of which are less than 2^63 ns apart.
  const bool whole = day == std::floor(day) && month == std::floor(month) &&
                     year == std::floor(year) && year >= 1970 && year <= 2199 && month >= 1 &&
                     month <= 12 && day >= 1 && day <= 31;
  const UtcDate d =
      whole ? UtcDate{static_cast<int>(year), static_cast<int>(month), static_cast<int>(day)}
            : UtcDate{0, 0, 0};
  if (!whole || !is_valid(d)) {
    throw core::InputError(
        f.where(1, "date"),
        fmt::format("'{},{},{}' is not a date dd,mm,yyyy", f.text(1), f.text(2), f.text(3)),
        "day 01-31, month 01-12, a four-digit year 1970-2199");
  }
  z.date = d;
  return z;
}

// "d.dd" degrees with an east/west letter at i + 1 → rad, + east; empty → NaN.
double east_west(const Fields& f, std::size_t i, const std::string& name) {
  const double deg = f.number(i, name);
  const char direction = f.letter(i + 1, name + "_direction", "EW");
  return (direction == 'W' ? -deg : deg) * kDegToRad;
}

// Seapath quality flag 0 normal, 1 reduced, 2 invalid; −1 if empty.
int seapath_quality(const Fields& f, std::size_t i, const std::string& name) {
  const double q = f.number(i, name);
  if (core::is_missing(q)) return -1;
  if (q != 0.0 && q != 1.0 && q != 2.0) {
    throw core::InputError(f.where(i, name),
                           fmt::format("quality '{}' is not 0, 1 or 2", f.text(i)),
                           "Seapath quality: 0 normal, 1 reduced, 2 invalid");
  }
  return static_cast<int>(q);
}

// Kongsberg Seapath PSXN,20/22/23 (Seapath 200 installation manual, appendix B); others stay
// NmeaOther.
void parse_psxn(NmeaSentence& out, bool lenient, const core::InputLocation& where) {
  if (out.fields.empty()) return;
  const std::string id = out.fields.front();
  std::vector<std::string> rest(out.fields.begin() + 1, out.fields.end());
  const Fields f(rest, where, "PSXN," + id);
  if (id == "20") {
    check_count(f, rest, "PSXN,20", {4}, 4, lenient);
    out.data =
        NmeaPsxnQuality{seapath_quality(f, 0, "horizontal"), seapath_quality(f, 1, "height"),
                        seapath_quality(f, 2, "heading"), seapath_quality(f, 3, "roll_pitch")};
  } else if (id == "22") {
    check_count(f, rest, "PSXN,22", {2}, 2, lenient);
    out.data = NmeaPsxnGyro{f.number(0, "gyro_calibration") * kDegToRad,
                            f.number(1, "gyro_offset") * kDegToRad};
  } else if (id == "23") {
    check_count(f, rest, "PSXN,23", {4}, 4, lenient);
    out.data = NmeaPsxnAttitude{f.number(0, "roll") * kDegToRad, f.number(1, "pitch") * kDegToRad,
                                f.heading(2), f.number(3, "heave")};
  }
}

// Decodes the standard (non-proprietary) types this module knows into out.data.
void decode(NmeaSentence& out, const Fields& f, bool lenient) {
  std::vector<std::string>& fs = out.fields;
  if (out.type == "GGA") {
    check_count(f, fs, "GGA", {14}, 10, lenient);
    out.data = parse_gga(f);
  } else if (out.type == "RMC") {
    check_count(f, fs, "RMC", {11, 12, 13}, 9, lenient);
    out.data = parse_rmc(f, fs.size());
  } else if (out.type == "VTG") {
    check_count(f, fs, "VTG", {8, 9}, 6, lenient);
    out.data = parse_vtg(f, fs.size());
  } else if (out.type == "GLL") {
    check_count(f, fs, "GLL", {6, 7}, 6, lenient);
    out.data = parse_gll(f);
  } else if (out.type == "ZDA") {
    check_count(f, fs, "ZDA", {6}, 4, lenient);
    out.data = parse_zda(f);
  } else if (out.type == "HDT") {
    check_count(f, fs, "HDT", {2}, 1, lenient);
    NmeaHdt h;
    h.heading_rad = f.heading(0);
    if (!f.empty(0)) f.letter(1, "heading_reference", "T");
    out.data = h;
  } else if (out.type == "THS") {
    check_count(f, fs, "THS", {2}, 2, lenient);
    out.data = NmeaThs{f.heading(0), f.letter(1, "mode", "AEMSV")};
  } else if (out.type == "HDG") {
    check_count(f, fs, "HDG", {5}, 1, lenient);
    out.data = NmeaHdg{f.heading(0), east_west(f, 1, "deviation"), east_west(f, 3, "variation")};
  } else if (out.type == "ROT") {
    check_count(f, fs, "ROT", {2}, 2, lenient);
    NmeaRot r;
    r.rate_rad_s = f.number(0, "rate") * kDegToRad / 60.0;
    r.valid = f.letter(1, "status", "AV") == 'A';
    out.data = r;
  }
}

}  // namespace

std::string to_iso(const UtcDate& date) {
  return fmt::format("{:04d}-{:02d}-{:02d}", date.year, date.month, date.day);
}

// Days from civil: the proleptic Gregorian calendar counted in 400-year eras of 146097 days,
// each year starting on 1 March so that the leap day is the last day of the year.
long days_since_epoch(const UtcDate& date) {
  const long y = date.year - (date.month <= 2 ? 1 : 0);
  const long era = (y >= 0 ? y : y - 399) / 400;
  const long year_of_era = y - era * 400;
  const long month_from_march = (date.month + 9) % 12;
  const long day_of_year = (153 * month_from_march + 2) / 5 + date.day - 1;
  const long day_of_era = year_of_era * 365 + year_of_era / 4 - year_of_era / 100 + day_of_year;
  return era * 146097 + day_of_era - 719468;
}

UtcDate add_days(const UtcDate& date, long days) {
  // Civil from days: the inverse of days_since_epoch().
  const long z = days_since_epoch(date) + days + 719468;
  const long era = (z >= 0 ? z : z - 146096) / 146097;
  const long day_of_era = z - era * 146097;
  const long year_of_era =
      (day_of_era - day_of_era / 1460 + day_of_era / 36524 - day_of_era / 146096) / 365;
  const long day_of_year = day_of_era - (365 * year_of_era + year_of_era / 4 - year_of_era / 100);
  const long month_from_march = (5 * day_of_year + 2) / 153;
  UtcDate out;
  out.day = static_cast<int>(day_of_year - (153 * month_from_march + 2) / 5 + 1);
  out.month = static_cast<int>(month_from_march < 10 ? month_from_march + 3 : month_from_march - 9);
  out.year = static_cast<int>(year_of_era + era * 400 + (out.month <= 2 ? 1 : 0));
  return out;
}

bool is_valid(const UtcDate& date) {
  if (date.month < 1 || date.month > 12 || date.day < 1) return false;
  constexpr int kDays[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  const bool leap = (date.year % 4 == 0 && date.year % 100 != 0) || date.year % 400 == 0;
  const int days = kDays[date.month - 1] + (date.month == 2 && leap ? 1 : 0);
  return date.day <= days;
}

std::uint8_t nmea_checksum(std::string_view body) {
  std::uint8_t sum = 0;
  for (const char c : body) sum ^= static_cast<std::uint8_t>(c);
  return sum;
}

NmeaSentence parse_nmea_sentence(std::string_view line, const core::InputLocation& where,
                                 const NmeaParseOptions& options) {
  const std::string_view text = detail::trim(line);
  const auto at = [&](std::optional<std::size_t> column, std::string name) {
    core::InputLocation location = where;
    location.column = column;
    location.column_name = std::move(name);
    return location;
  };
  if (text.empty() || text[0] != '$') {
    throw core::InputError(
        at(1, "start"), "the line does not start with '$'",
        "each line must be one NMEA 0183 sentence \"$TTSSS,…*hh\"; remove logger time stamps "
        "or other text before the '$'");
  }
  NmeaSentence out;
  std::string_view body = text.substr(1);
  const std::size_t star = body.rfind('*');
  if (star != std::string_view::npos) {
    const std::string_view given = body.substr(star + 1);
    body = body.substr(0, star);
    const auto hex = [](char c) {
      return (c >= '0' && c <= '9') || (c >= 'A' && c <= 'F') || (c >= 'a' && c <= 'f');
    };
    if (given.size() != 2 || !hex(given[0]) || !hex(given[1])) {
      throw core::InputError(at(std::nullopt, "checksum"),
                             fmt::format("checksum '*{}' is not two hex digits", given),
                             "a sentence ends with '*' and two hex digits, e.g. *47");
    }
    const unsigned expected = std::stoul(std::string(given), nullptr, 16);
    const unsigned actual = nmea_checksum(body);
    if (expected != actual) {
      throw core::InputError(
          at(std::nullopt, "checksum"),
          fmt::format("checksum mismatch: the sentence says {:02X}, its text gives {:02X}",
                      expected, actual),
          "the line is corrupted (a changed or lost character); drop it or fix the source");
    }
    out.has_checksum = true;
  }
  // Address, then fields split at ','.
  std::size_t start = 0;
  std::vector<std::string> parts;
  while (true) {
    const std::size_t comma = body.find(',', start);
    parts.emplace_back(body.substr(start, comma - start));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  const std::string& address = parts.front();
  bool alnum = !address.empty();
  for (const char c : address) alnum = alnum && ((c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'));
  const bool proprietary = alnum && address[0] == 'P';
  if (!alnum || (!proprietary && address.size() != 5)) {
    throw core::InputError(
        at(1, "address"), fmt::format("'{}' is not an NMEA address", address),
        "the address is a two-letter talker ID and a three-letter type, e.g. GPGGA");
  }
  out.talker = proprietary ? "P" : address.substr(0, 2);
  out.type = proprietary ? address.substr(1) : address.substr(2);
  out.fields.assign(parts.begin() + 1, parts.end());
  const Fields f(out.fields, where, out.type);
  const bool lenient = options.lenient_field_count;
  if (proprietary) {
    if (out.type == "SXN") parse_psxn(out, lenient, where);
    return out;
  }
  decode(out, f, lenient);
  return out;
}

}  // namespace dynpos::io
