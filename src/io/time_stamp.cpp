#include "dynpos/io/time_stamp.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "text_util.hpp"
#include "time_units.hpp"

namespace dynpos::io {
namespace {

using core::InputError;
using core::InputLocation;

using detail::kNsPerDay;
using detail::kNsPerS;
// Days whose every nanosecond (and a day of zone offset) fits int64 ns: 1677-09-23…2262-04-10.
constexpr std::int64_t kFirstDay = -106'750;
constexpr std::int64_t kLastDay = 106'749;

struct FormatName {
  TimeFormat format;
  std::string_view name;
};
constexpr std::array<FormatName, 9> kFormatNames{{
    {TimeFormat::kAuto, "auto"},
    {TimeFormat::kSeconds, "seconds"},
    {TimeFormat::kEpochSeconds, "epoch-s"},
    {TimeFormat::kEpochMillis, "epoch-ms"},
    {TimeFormat::kEpochMicros, "epoch-us"},
    {TimeFormat::kEpochNanos, "epoch-ns"},
    {TimeFormat::kIso8601, "iso8601"},
    {TimeFormat::kTimeOfDay, "time-of-day"},
    {TimeFormat::kSecNsec, "sec-nsec"},
}};

bool is_digit(char c) noexcept { return c >= '0' && c <= '9'; }

// Exactly `n` digits at s[pos]; advances pos.
bool read_digits(std::string_view s, std::size_t& pos, std::size_t n, unsigned& out) noexcept {
  if (pos + n > s.size()) return false;
  unsigned v = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const char c = s[pos + i];
    if (!is_digit(c)) return false;
    v = v * 10 + static_cast<unsigned>(c - '0');
  }
  pos += n;
  out = v;
  return true;
}

// A fraction after '.', at s[pos] (pos on the '.'): nanoseconds, digits beyond 9 truncated.
// No '.' leaves pos and gives 0; a '.' without digits fails.
bool read_fraction_ns(std::string_view s, std::size_t& pos, std::int64_t& ns) noexcept {
  ns = 0;
  if (pos >= s.size() || s[pos] != '.') return true;
  ++pos;
  std::size_t digits = 0;
  std::int64_t scale = kNsPerS;
  while (pos < s.size() && is_digit(s[pos])) {
    if (digits < 9) {
      scale /= 10;
      ns += scale * (s[pos] - '0');
    }
    ++digits;
    ++pos;
  }
  return digits > 0;
}

// hh:mm[:ss[.f…]] at s[pos] → nanoseconds since midnight. The hour has 1 or 2 digits. With
// `leap`, a leap second hh:59:60[.f…] is read as the next minute's first second and flagged.
std::optional<std::int64_t> read_clock(std::string_view s, std::size_t& pos,
                                       bool* leap = nullptr) noexcept {
  unsigned h = 0, m = 0, sec = 0;
  const std::size_t hour_digits = pos + 1 < s.size() && s[pos + 1] == ':' ? 1 : 2;
  if (!read_digits(s, pos, hour_digits, h) || pos >= s.size() || s[pos] != ':') {
    return std::nullopt;
  }
  ++pos;
  if (!read_digits(s, pos, 2, m)) return std::nullopt;
  std::int64_t fraction = 0;
  if (pos < s.size() && s[pos] == ':') {
    ++pos;
    if (!read_digits(s, pos, 2, sec) || !read_fraction_ns(s, pos, fraction)) return std::nullopt;
  }
  const bool leap_second = leap != nullptr && sec == 60 && m == 59;
  if (h > 23 || m > 59 || (sec > 59 && !leap_second)) return std::nullopt;
  if (leap != nullptr) *leap = leap_second;
  return ((h * 60 + m) * 60 + sec) * kNsPerS + fraction;
}

// YYYY-MM-DD or YYYY/MM/DD at s[pos] → days since 1970-01-01.
std::optional<std::int64_t> read_date(std::string_view s, std::size_t& pos) noexcept {
  unsigned y = 0, m = 0, d = 0;
  if (!read_digits(s, pos, 4, y) || pos >= s.size()) return std::nullopt;
  const char separator = s[pos];
  if (separator != '-' && separator != '/') return std::nullopt;
  ++pos;
  if (!read_digits(s, pos, 2, m) || pos >= s.size() || s[pos] != separator) return std::nullopt;
  ++pos;
  if (!read_digits(s, pos, 2, d) || !is_valid_date({y, m, d})) return std::nullopt;
  return days_from_civil(y, m, d);
}

// Z, ±hh:mm, ±hhmm or ±hh at s[pos] (after at most one space) up to the end; nullopt offset
// when nothing follows.
bool read_zone(std::string_view s, std::size_t pos, std::optional<int>& offset_min) noexcept {
  offset_min.reset();
  if (pos < s.size() && s[pos] == ' ') ++pos;
  if (pos == s.size()) return true;
  if (s[pos] == 'Z' || s[pos] == 'z') {
    offset_min = 0;
    return pos + 1 == s.size();
  }
  if (s[pos] != '+' && s[pos] != '-') return false;
  const int sign = s[pos] == '-' ? -1 : 1;
  ++pos;
  unsigned h = 0, m = 0;
  if (!read_digits(s, pos, 2, h)) return false;
  const bool colon = pos < s.size() && s[pos] == ':';
  if (colon) ++pos;
  if ((colon || pos < s.size()) && !read_digits(s, pos, 2, m)) return false;
  if (pos != s.size() || h > 23 || m > 59) return false;
  offset_min = sign * static_cast<int>(h * 60 + m);
  return true;
}

// A decimal number's sign, integer digits and fraction digits; false unless it is one.
struct DecimalText {
  bool negative = false;
  std::string_view whole, fraction;
};
bool split_decimal(std::string_view s, DecimalText& out) noexcept {
  out = {};
  if (!s.empty() && (s.front() == '-' || s.front() == '+')) {
    out.negative = s.front() == '-';
    s.remove_prefix(1);
  }
  const std::size_t dot = s.find('.');
  out.whole = s.substr(0, dot);
  out.fraction = dot == std::string_view::npos ? std::string_view() : s.substr(dot + 1);
  if (out.whole.empty() && out.fraction.empty()) return false;
  for (const char c : out.whole) {
    if (!is_digit(c)) return false;
  }
  for (const char c : out.fraction) {
    if (!is_digit(c)) return false;
  }
  return dot == std::string_view::npos || !out.fraction.empty();
}

std::optional<double> parse_double(std::string_view text) noexcept {
  if (text.size() > 1 && text.front() == '+') text.remove_prefix(1);
  double value = 0.0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || ptr != text.data() + text.size() || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

std::optional<std::int64_t> parse_int(std::string_view text) noexcept {
  if (text.size() > 1 && text.front() == '+') text.remove_prefix(1);
  std::int64_t value = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || ptr != text.data() + text.size()) return std::nullopt;
  return value;
}

// "+hh:mm" of an offset in minutes.
std::string offset_text(int offset_min) {
  const int a = offset_min < 0 ? -offset_min : offset_min;
  return fmt::format("{}{:02}:{:02}", offset_min < 0 ? '-' : '+', a / 60, a % 60);
}

}  // namespace

std::string_view time_format_name(TimeFormat format) noexcept {
  for (const auto& entry : kFormatNames) {
    if (entry.format == format) return entry.name;
  }
  return "auto";
}

std::optional<TimeFormat> find_time_format(std::string_view name) noexcept {
  for (const auto& entry : kFormatNames) {
    if (entry.name == name) return entry.format;
  }
  return std::nullopt;
}

std::string time_format_names() {
  std::vector<std::string> names;
  for (const auto& entry : kFormatNames) names.emplace_back(entry.name);
  return detail::join(names);
}

std::string_view time_order_name(TimeOrder order) noexcept {
  switch (order) {
    case TimeOrder::kDropDuplicates:
      return "drop-duplicates";
    case TimeOrder::kDropNonIncreasing:
      return "drop-non-increasing";
    default:
      return "error";
  }
}

std::optional<TimeOrder> find_time_order(std::string_view name) noexcept {
  for (const TimeOrder order :
       {TimeOrder::kError, TimeOrder::kDropDuplicates, TimeOrder::kDropNonIncreasing}) {
    if (time_order_name(order) == name) return order;
  }
  return std::nullopt;
}

void TimeStampOptions::validate() const {
  if (!date.empty() && !parse_date_days(date)) {
    throw InputError::for_option("date", fmt::format("'{}' is not a date", date),
                                 "write it as YYYY-MM-DD, e.g. 2024-05-01");
  }
}

bool is_valid_date(const CivilDate& date) noexcept {
  const auto [year, month, day] = date;
  if (month < 1 || month > 12 || day < 1) return false;
  constexpr std::array<unsigned, 12> kDays{31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  const bool leap = year % 4 == 0 && (year % 100 != 0 || year % 400 == 0);
  return day <= kDays[month - 1] + (month == 2 && leap ? 1 : 0);
}

std::optional<ParsedStamp> parse_iso8601(std::string_view text) noexcept {
  const std::string_view s = detail::trim(text);
  std::size_t pos = 0;
  const std::optional<std::int64_t> date_days = read_date(s, pos);
  if (!date_days || pos >= s.size()) return std::nullopt;
  const std::int64_t days = *date_days;
  if (days < kFirstDay || days > kLastDay) return std::nullopt;  // outside int64 ns
  if (s[pos] != 'T' && s[pos] != 't' && s[pos] != ' ') return std::nullopt;
  ++pos;
  ParsedStamp out;
  const std::optional<std::int64_t> clock = read_clock(s, pos, &out.leap_second);
  if (!clock) return std::nullopt;
  const std::int64_t clock_ns = *clock;
  if (!read_zone(s, pos, out.utc_offset_min)) return std::nullopt;
  out.ns = days * kNsPerDay + clock_ns -
           static_cast<std::int64_t>(out.utc_offset_min.value_or(0)) * 60 * kNsPerS;
  // A zoned leap second is the last second of a UTC day (23:59:60Z, 01:59:60+02:00).
  if (out.leap_second && out.utc_offset_min &&
      (out.ns % kNsPerDay + kNsPerDay) % kNsPerDay >= kNsPerS) {
    return std::nullopt;
  }
  return out;
}

std::optional<std::int64_t> parse_date_days(std::string_view text) noexcept {
  const std::string_view s = detail::trim(text);
  std::size_t pos = 0;
  const std::optional<std::int64_t> days = read_date(s, pos);
  if (!days || pos != s.size()) return std::nullopt;
  if (*days < kFirstDay || *days > kLastDay) return std::nullopt;  // outside int64 ns
  return days;
}

std::optional<std::int64_t> parse_time_of_day_ns(std::string_view text) noexcept {
  const std::string_view s = detail::trim(text);
  std::size_t pos = 0;
  const std::optional<std::int64_t> ns = read_clock(s, pos);
  if (!ns || pos != s.size()) return std::nullopt;
  return ns;
}

std::optional<std::int64_t> parse_decimal_ns(std::string_view text, int exponent) noexcept {
  const std::string_view s = detail::trim(text);
  if (exponent < 0 || exponent > 9) return std::nullopt;
  std::int64_t unit_ns = 1;  // nanoseconds per unit
  for (int k = exponent; k < 9; ++k) unit_ns *= 10;
  if (s.find_first_of("eE") != std::string_view::npos) {
    const std::optional<double> value = parse_double(s);
    if (!value) return std::nullopt;
    const double ns = *value * static_cast<double>(unit_ns);
    if (!(std::fabs(ns) < 9.2e18)) return std::nullopt;
    return static_cast<std::int64_t>(std::llround(ns));
  }
  DecimalText d;
  if (!split_decimal(s, d)) return std::nullopt;
  std::int64_t whole = 0;
  for (const char c : d.whole) {
    if (__builtin_mul_overflow(whole, 10, &whole) || __builtin_add_overflow(whole, c - '0', &whole))
      return std::nullopt;
  }
  std::int64_t ns = 0;
  if (__builtin_mul_overflow(whole, unit_ns, &ns)) return std::nullopt;
  std::int64_t scale = unit_ns, fraction_ns = 0;  // fraction_ns < unit_ns
  for (std::size_t i = 0; i < d.fraction.size() && scale > 1; ++i) {
    scale /= 10;
    fraction_ns += scale * (d.fraction[i] - '0');
  }
  if (__builtin_add_overflow(ns, fraction_ns, &ns)) return std::nullopt;
  return d.negative ? -ns : ns;
}

std::optional<std::int64_t> parse_unpadded_ns(std::string_view text) noexcept {
  DecimalText d;
  if (!split_decimal(detail::trim(text), d) || d.negative || d.whole.empty() ||
      d.fraction.empty() || d.fraction.size() > 9) {
    return std::nullopt;
  }
  const std::optional<std::int64_t> whole = parse_int(d.whole);
  const std::optional<std::int64_t> nsec = parse_int(d.fraction);
  if (!whole || !nsec || *whole > std::numeric_limits<std::int64_t>::max() / kNsPerS - 1) {
    return std::nullopt;
  }
  return *whole * kNsPerS + *nsec;
}

std::string format_iso8601(std::int64_t ns, std::optional<int> utc_offset_min) {
  const std::int64_t local =
      ns + static_cast<std::int64_t>(utc_offset_min.value_or(0)) * 60 * kNsPerS;
  std::int64_t days = local / kNsPerDay;
  std::int64_t in_day = local % kNsPerDay;
  if (in_day < 0) {
    in_day += kNsPerDay;
    --days;
  }
  // civil_from_days (H. Hinnant), the inverse of days_from_civil().
  const std::int64_t z = days + 719468;
  const std::int64_t era = (z >= 0 ? z : z - 146096) / 146097;
  const auto doe = static_cast<unsigned>(z - era * 146097);
  const unsigned yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  const unsigned doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const unsigned mp = (5 * doy + 2) / 153;
  const unsigned d = doy - (153 * mp + 2) / 5 + 1;
  const unsigned m = mp < 10 ? mp + 3 : mp - 9;
  const std::int64_t y = static_cast<std::int64_t>(yoe) + era * 400 + (m <= 2 ? 1 : 0);

  const std::int64_t s = in_day / kNsPerS;
  const std::int64_t f = in_day % kNsPerS;
  std::string out =
      fmt::format("{:04}-{:02}-{:02}T{:02}:{:02}:{:02}", y, m, d, s / 3600, s / 60 % 60, s % 60);
  if (f % 1'000'000 == 0 && f != 0) {
    out += fmt::format(".{:03}", f / 1'000'000);
  } else if (f % 1'000 == 0 && f != 0) {
    out += fmt::format(".{:06}", f / 1'000);
  } else if (f != 0) {
    out += fmt::format(".{:09}", f);
  }
  if (utc_offset_min) out += *utc_offset_min == 0 ? "Z" : offset_text(*utc_offset_min);
  return out;
}

namespace {

// One cell read both ways: its fraction as decimals, and as integer nanoseconds.
struct FractionReadings {
  std::int64_t decimal_ns = 0;   // relative to the first cell
  std::int64_t unpadded_ns = 0;  // relative to the first cell
  std::size_t digits = 0;        // fraction digits
  bool leading_zero = false;     // "05": never an unpadded integer
};

// The fraction digits of a cell as FractionReadings describes them.
FractionReadings fraction_of(std::string_view digits) {
  return {0, 0, digits.size(), digits.size() > 1 && digits.front() == '0'};
}

double median_of(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// The largest departure of a step from the median step.
double largest_departure(const std::vector<double>& steps) {
  const double m = median_of(steps);
  double out = 0.0;
  for (const double d : steps) out = std::max(out, std::abs(d - m));
  return out;
}

// A slow logger (1–2 Hz) with the bug never goes back read as decimals, but where its fraction
// changes length (0.099999999 s written "99999999", then 0.100000123 s "100000123") the decimal
// reading jumps off its pace while the nanosecond reading keeps it: both lengths seen, 9 digits
// among them, and the nanosecond reading's largest departure from its median step a tenth of the
// decimal reading's at most, which departs by a tenth of its step at least.
bool slow_logger_evidence(std::span<const FractionReadings> rows,
                          const std::vector<double>& ns_steps,
                          const std::vector<double>& decimal_steps) {
  bool nine = false, shorter = false;
  for (const FractionReadings& r : rows) {
    nine = nine || r.digits == 9;
    shorter = shorter || r.digits < 9;
  }
  if (!nine || !shorter || ns_steps.size() < 2 || decimal_steps.size() != ns_steps.size()) {
    return false;
  }
  const double decimal_departure = largest_departure(decimal_steps);
  return decimal_departure >= 0.1 * median_of(decimal_steps) &&
         largest_departure(ns_steps) <= 0.1 * decimal_departure;
}

// The exporter bug's signature is systematic: read as unpadded nanoseconds the stamps never go
// back and run at the logger's own pace; read as decimals they go back where the fraction
// grows longer ("16.99…" then "16.1…"). One row out of order in a decimal log also goes back
// from a shorter to a longer fraction ("12.9" then "12.85"), but read as nanoseconds its rows
// then crowd into nanoseconds and jump by whole seconds: the median step tells the two apart.
// A fraction with a leading zero ("12.05") is no unpadded integer: decimals.
bool unpadded_evidence(std::span<const FractionReadings> rows) {
  std::size_t decimal_backs = 0;
  std::vector<double> ns_steps, decimal_steps;
  for (const FractionReadings& r : rows) {
    if (r.leading_zero) return false;
  }
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const FractionReadings& a = rows[i - 1];
    const FractionReadings& b = rows[i];
    if (b.unpadded_ns <= a.unpadded_ns) return false;  // back or repeated: not this bug
    ns_steps.push_back(static_cast<double>(b.unpadded_ns - a.unpadded_ns));
    if (b.decimal_ns < a.decimal_ns) {
      if (b.digits <= a.digits) return false;  // back without a longer fraction
      ++decimal_backs;
    } else if (b.decimal_ns > a.decimal_ns) {
      decimal_steps.push_back(static_cast<double>(b.decimal_ns - a.decimal_ns));
    }
  }
  if (decimal_steps.empty()) return false;
  if (decimal_backs == 0) return slow_logger_evidence(rows, ns_steps, decimal_steps);
  // The logger's pace read both ways agrees within a factor of ten for the bug; for a decimal
  // log with rows out of order the nanosecond reading's median step is below a microsecond.
  return median_of(ns_steps) >= 0.1 * median_of(decimal_steps);
}

// An ISO 8601 stamp without its fraction, and the fraction's digits; nullopt without one.
struct IsoFraction {
  std::string whole;  // the stamp with ".digits" taken out
  std::string_view digits;
};
std::optional<IsoFraction> split_iso_fraction(std::string_view text) {
  const std::string_view s = detail::trim(text);
  const std::size_t dot = s.find('.');
  if (dot == std::string_view::npos) return std::nullopt;
  std::size_t end = dot + 1;
  while (end < s.size() && is_digit(s[end])) ++end;
  if (end == dot + 1) return std::nullopt;
  IsoFraction out;
  out.whole = std::string(s.substr(0, dot)) + std::string(s.substr(end));
  out.digits = s.substr(dot + 1, end - dot - 1);
  return out;
}

}  // namespace

bool looks_like_unpadded_ns(std::span<const std::string_view> cells) {
  std::vector<FractionReadings> rows;
  std::optional<double> first_decimal;
  std::optional<std::int64_t> first_ns;
  for (const std::string_view cell : cells) {
    const std::string_view text = detail::trim(cell);
    if (text.empty()) continue;
    const std::optional<std::int64_t> ns = parse_unpadded_ns(text);
    const std::optional<double> decimal = parse_double(text);
    if (!ns || !decimal) return false;
    if (!first_ns) {
      first_ns = ns;
      first_decimal = decimal;
    }
    // Decimal seconds to integer ns about the first cell: exact enough for the order and pace.
    FractionReadings row = fraction_of(text.substr(text.find('.') + 1));
    row.decimal_ns = std::llround((*decimal - *first_decimal) * 1e9);
    row.unpadded_ns = *ns - *first_ns;
    rows.push_back(row);
  }
  return unpadded_evidence(rows);
}

std::optional<ParsedStamp> parse_iso8601_unpadded_ns(std::string_view text) noexcept {
  try {
    const std::optional<IsoFraction> split = split_iso_fraction(text);
    if (!split || split->digits.size() > 9) return std::nullopt;
    std::optional<ParsedStamp> stamp = parse_iso8601(split->whole);
    const std::optional<std::int64_t> nsec = parse_int(split->digits);
    if (!stamp || !nsec || stamp->leap_second) return std::nullopt;
    stamp->ns += *nsec;
    return stamp;
  } catch (...) {  // std::bad_alloc of the copy
    return std::nullopt;
  }
}

bool looks_like_unpadded_iso8601(std::span<const std::string_view> cells) {
  std::vector<FractionReadings> rows;
  std::optional<std::int64_t> first_decimal, first_ns;
  for (const std::string_view cell : cells) {
    if (detail::trim(cell).empty()) continue;
    const std::optional<ParsedStamp> decimal = parse_iso8601(cell);
    const std::optional<ParsedStamp> ns = parse_iso8601_unpadded_ns(cell);
    if (!decimal || !ns) return false;
    if (!first_ns) {
      first_ns = ns->ns;
      first_decimal = decimal->ns;
    }
    FractionReadings row = fraction_of(split_iso_fraction(cell)->digits);
    row.decimal_ns = decimal->ns - *first_decimal;
    row.unpadded_ns = ns->ns - *first_ns;
    rows.push_back(row);
  }
  return unpadded_evidence(rows);
}

std::optional<TimeStampFormat> detect_time_format(std::span<const std::string_view> cells) {
  std::string_view first;
  for (const std::string_view cell : cells) {
    first = detail::trim(cell);
    if (!first.empty()) break;
  }
  if (first.empty()) return std::nullopt;
  if (parse_iso8601(first)) {
    return TimeStampFormat{TimeFormat::kIso8601, looks_like_unpadded_iso8601(cells)};
  }
  if (parse_time_of_day_ns(first)) return TimeStampFormat{TimeFormat::kTimeOfDay, false};
  const std::optional<double> value = parse_double(first);
  if (!value) return std::nullopt;
  const double a = std::fabs(*value);
  TimeStampFormat out{TimeFormat::kSeconds, false};
  if (a >= 1e9 && a < 1e10) {
    out.format = TimeFormat::kEpochSeconds;
  } else if (a >= 1e12 && a < 1e13) {
    out.format = TimeFormat::kEpochMillis;
  } else if (a >= 1e15 && a < 1e16) {
    out.format = TimeFormat::kEpochMicros;
  } else if (a >= 1e18 && a < 1e19) {
    out.format = TimeFormat::kEpochNanos;
  }
  if (out.format == TimeFormat::kSeconds || out.format == TimeFormat::kEpochSeconds) {
    out.unpadded_ns = looks_like_unpadded_ns(cells);
  }
  return out;
}

}  // namespace dynpos::io
