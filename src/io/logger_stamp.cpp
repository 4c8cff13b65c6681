#include "logger_stamp.hpp"

#include <fmt/core.h>

#include <vector>

#include "dynpos/io/nmea_sentence.hpp"

namespace dynpos::io::detail {
namespace {

constexpr std::int64_t kSecond_ns = 1'000'000'000;

// Reads `n` digits at text[pos…] into value; false if they are not all digits.
bool digits(std::string_view text, std::size_t pos, std::size_t n, int& value) {
  if (pos + n > text.size()) return false;
  value = 0;
  for (std::size_t k = pos; k < pos + n; ++k) {
    if (text[k] < '0' || text[k] > '9') return false;
    value = value * 10 + (text[k] - '0');
  }
  return true;
}

// The instants a stamp may name: 1970-01-01 to 2200-01-01 UTC, so that any two of a capture
// are less than 2^63 ns apart (a span of 1677…2262 overflowed the difference).
constexpr std::int64_t kLastStamp_s = 7'258'118'400;

// seconds·10⁹ + fraction [ns]; nullopt outside 1970…2200.
std::optional<std::int64_t> to_ns(std::int64_t seconds, std::int64_t fraction_ns) {
  if (seconds < 0 || seconds >= kLastStamp_s) return std::nullopt;
  return seconds * kSecond_ns + fraction_ns;
}

// ".f…" at text[pos…] (up to nine digits kept) → ns; advances pos. No dot: 0.
std::optional<std::int64_t> fraction_ns(std::string_view text, std::size_t& pos) {
  if (pos >= text.size() || text[pos] != '.') return 0;
  ++pos;
  const std::size_t first = pos;
  std::int64_t ns = 0, scale = kSecond_ns / 10;
  for (; pos < text.size() && text[pos] >= '0' && text[pos] <= '9'; ++pos, scale /= 10) {
    ns += (text[pos] - '0') * scale;
  }
  if (pos == first) return std::nullopt;
  return ns;
}

std::optional<LoggerStamp> parse_iso(std::string_view text) {
  UtcDate date;
  int hh = 0, mm = 0, ss = 0;
  if (text.size() < 19 || text[4] != '-' || text[7] != '-' ||
      (text[10] != 'T' && text[10] != ' ') || text[13] != ':' || text[16] != ':' ||
      !digits(text, 0, 4, date.year) || !digits(text, 5, 2, date.month) ||
      !digits(text, 8, 2, date.day) || !digits(text, 11, 2, hh) || !digits(text, 14, 2, mm) ||
      !digits(text, 17, 2, ss) || !is_valid(date) || hh > 23 || mm > 59 || ss > 60) {
    return std::nullopt;
  }
  std::size_t pos = 19;
  const std::optional<std::int64_t> fraction = fraction_ns(text, pos);
  if (!fraction) return std::nullopt;
  LoggerStamp out;
  out.form = "iso8601";
  std::int64_t offset_s = 0;
  if (pos < text.size() && text[pos] == 'Z') {
    ++pos;
  } else if (pos < text.size() && (text[pos] == '+' || text[pos] == '-')) {
    int oh = 0, om = 0;
    if (!digits(text, pos + 1, 2, oh) || pos + 3 >= text.size() || text[pos + 3] != ':' ||
        !digits(text, pos + 4, 2, om) || oh > 23 || om > 59) {
      return std::nullopt;
    }
    offset_s = (text[pos] == '-' ? -1 : 1) * (oh * 3600 + om * 60);
    pos += 6;
  } else {
    out.zone_given = false;
  }
  if (pos != text.size()) return std::nullopt;
  const std::int64_t seconds = days_since_epoch(date) * 86400 + hh * 3600 + mm * 60 + ss - offset_s;
  const std::optional<std::int64_t> ns = to_ns(seconds, *fraction);
  if (!ns) return std::nullopt;
  out.unix_ns = *ns;
  return out;
}

std::optional<LoggerStamp> parse_epoch_seconds(std::string_view text) {
  std::size_t pos = 0;
  std::int64_t seconds = 0;
  for (; pos < text.size() && text[pos] >= '0' && text[pos] <= '9'; ++pos) {
    if (pos >= 12) return std::nullopt;  // beyond year 33000: not a stamp
    seconds = seconds * 10 + (text[pos] - '0');
  }
  // At least nine digits (2001-09-09 onwards) so that a plain count is not taken for a stamp.
  if (pos < 9) return std::nullopt;
  const std::optional<std::int64_t> fraction = fraction_ns(text, pos);
  if (!fraction || pos != text.size()) return std::nullopt;
  const std::optional<std::int64_t> ns = to_ns(seconds, *fraction);
  if (!ns) return std::nullopt;
  return LoggerStamp{*ns, "epoch seconds", true};
}

}  // namespace

std::optional<LoggerStamp> parse_logger_stamp(std::string_view text) {
  if (std::optional<LoggerStamp> iso = parse_iso(text)) return iso;
  return parse_epoch_seconds(text);
}

std::optional<LoggerStamp> find_logger_stamp(std::string_view prefix) {
  std::vector<std::string_view> tokens;
  std::size_t start = 0;
  for (std::size_t k = 0; k <= prefix.size(); ++k) {
    const bool separator = k == prefix.size() || prefix[k] == ' ' || prefix[k] == '\t' ||
                           prefix[k] == ',' || prefix[k] == ';';
    if (!separator) continue;
    if (k > start) tokens.push_back(prefix.substr(start, k - start));
    start = k + 1;
  }
  if (tokens.empty()) return std::nullopt;
  if (std::optional<LoggerStamp> one = parse_logger_stamp(tokens.back())) return one;
  if (tokens.size() < 2) return std::nullopt;
  const std::string two = std::string(tokens[tokens.size() - 2]) + " " + std::string(tokens.back());
  return parse_logger_stamp(two);
}

std::string iso8601_utc(std::int64_t unix_ns) {
  std::int64_t days = unix_ns / kDay_ns;
  std::int64_t in_day = unix_ns % kDay_ns;
  if (in_day < 0) {
    in_day += kDay_ns;
    --days;
  }
  const UtcDate date = add_days(UtcDate{}, static_cast<long>(days));
  const std::int64_t s = in_day / kSecond_ns, ns = in_day % kSecond_ns;
  std::string fraction = fmt::format("{:09d}", ns);
  while (fraction.size() > 3 && fraction.back() == '0') fraction.pop_back();
  return fmt::format("{}T{:02d}:{:02d}:{:02d}.{}Z", to_iso(date), s / 3600, s / 60 % 60, s % 60,
                     fraction);
}

}  // namespace dynpos::io::detail
