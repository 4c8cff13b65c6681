#include "dynpos/live/stream_clock.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>

#include "dynpos/io/time_stamp.hpp"

namespace dynpos::live {
namespace {

constexpr double kDay_s = 86400.0;

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '"')) {
    s.remove_prefix(1);
  }
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '"' ||
                        s.back() == '\r' || s.back() == '\n')) {
    s.remove_suffix(1);
  }
  return s;
}

// The field `index` (0 = the address) of a sentence, up to '*'.
std::string_view sentence_field(std::string_view sentence, std::size_t index) {
  sentence = sentence.substr(0, sentence.find('*'));
  for (std::size_t i = 0; i < index; ++i) {
    const std::size_t comma = sentence.find(',');
    if (comma == std::string_view::npos) return {};
    sentence.remove_prefix(comma + 1);
  }
  return sentence.substr(0, sentence.find(','));
}

std::optional<double> plain_number(std::string_view text) {
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

// A cell or a logger stamp as seconds: a number, an ISO 8601 date-time, a time of day.
std::optional<double> stamp_seconds(std::string_view text) {
  text = trim(text);
  if (text.empty()) return std::nullopt;
  if (const auto s = plain_number(text)) return s;
  if (const auto stamp = io::parse_iso8601(text)) return static_cast<double>(stamp->ns) * 1e-9;
  if (const auto ns = io::parse_time_of_day_ns(text)) return static_cast<double>(*ns) * 1e-9;
  return std::nullopt;
}

}  // namespace

std::optional<double> nmea_time_of_day(std::string_view field) noexcept {
  if (field.size() < 6) return std::nullopt;
  for (std::size_t i = 0; i < 6; ++i) {
    if (field[i] < '0' || field[i] > '9') return std::nullopt;
  }
  const auto two = [&](std::size_t i) { return (field[i] - '0') * 10 + (field[i + 1] - '0'); };
  double fraction = 0.0;
  if (field.size() > 6) {
    const auto f = plain_number(field.substr(6));
    if (!f || field[6] != '.') return std::nullopt;
    fraction = *f;
  }
  return two(0) * 3600.0 + two(2) * 60.0 + two(4) + fraction;
}

std::optional<double> StreamClock::read(std::string_view line) {
  const std::size_t dollar = line.find('$');
  if (dollar != std::string_view::npos && !column_index_) return read_nmea(line, dollar);
  return read_csv(line);
}

std::optional<double> StreamClock::read_nmea(std::string_view line, std::size_t dollar) {
  if (dollar > 0) {  // a logger stamp: its last two tokens ("2024-05-01 10:00:00.1"), or last
    const std::string_view prefix = trim(line.substr(0, dollar));
    const std::size_t cut = prefix.find_last_of(" \t,;");
    if (cut != std::string_view::npos) {
      const std::size_t before = prefix.substr(0, cut).find_last_of(" \t,;");
      const auto two =
          stamp_seconds(before == std::string_view::npos ? prefix : prefix.substr(before + 1));
      if (two && prefix[cut] == ' ') return two;
    }
    const auto stamp =
        stamp_seconds(cut == std::string_view::npos ? prefix : prefix.substr(cut + 1));
    if (stamp) return stamp;
  }
  const std::string_view sentence = line.substr(dollar);
  const std::string_view address = sentence_field(sentence, 0);
  if (address.size() < 6) return std::nullopt;
  const std::string_view type = address.substr(address.size() - 3);
  std::size_t index = 0;
  if (type == "GGA" || type == "RMC" || type == "ZDA") index = 1;
  if (type == "GLL") index = 5;
  if (index == 0) return std::nullopt;
  const auto utc = nmea_time_of_day(sentence_field(sentence, index));
  if (!utc) return std::nullopt;
  if (last_utc_s_ && *utc < *last_utc_s_ - kDay_s / 2) day_offset_s_ += kDay_s;
  last_utc_s_ = *utc;
  return *utc + day_offset_s_;
}

std::optional<double> StreamClock::read_csv(std::string_view line) {
  const std::string_view text = trim(line);
  if (text.empty() || text.starts_with('#')) return std::nullopt;
  if (!column_index_) {  // the header: find the delimiter and the time column
    std::array<std::size_t, 3> counts{};
    constexpr std::array<char, 3> kDelimiters{',', ';', '\t'};
    for (const char c : text) {
      for (std::size_t k = 0; k < kDelimiters.size(); ++k) counts[k] += c == kDelimiters[k];
    }
    std::size_t best = 0;
    for (std::size_t k = 1; k < kDelimiters.size(); ++k) best = counts[k] > counts[best] ? k : best;
    delimiter_ = kDelimiters[best];
    std::string_view rest = text;
    for (std::size_t i = 0;; ++i) {
      const std::size_t end = rest.find(delimiter_);
      const std::string_view cell = trim(rest.substr(0, end));
      if (cell == time_column_ ||
          (cell.starts_with(time_column_) && cell.substr(time_column_.size()).starts_with(" ["))) {
        column_index_ = i;
        break;
      }
      if (end == std::string_view::npos) break;
      rest.remove_prefix(end + 1);
    }
    return std::nullopt;
  }
  std::string_view rest = text;
  for (std::size_t i = 0; i < *column_index_; ++i) {
    const std::size_t end = rest.find(delimiter_);
    if (end == std::string_view::npos) return std::nullopt;
    rest.remove_prefix(end + 1);
  }
  return stamp_seconds(rest.substr(0, rest.find(delimiter_)));
}

}  // namespace dynpos::live
