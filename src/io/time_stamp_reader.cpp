#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "dynpos/io/time_stamp.hpp"
#include "text_util.hpp"
#include "time_units.hpp"

namespace dynpos::io {
namespace {

using core::InputError;
using core::InputLocation;

using detail::kNsPerDay;
using detail::kNsPerS;
constexpr std::int64_t kRolloverNs = 12 * 3'600 * kNsPerS;  // a day ends when time goes back more

int epoch_exponent(TimeFormat format) {
  switch (format) {
    case TimeFormat::kEpochMillis:
      return 3;
    case TimeFormat::kEpochMicros:
      return 6;
    case TimeFormat::kEpochNanos:
      return 9;
    default:
      return 0;
  }
}

bool is_epoch(TimeFormat format) {
  return format == TimeFormat::kEpochSeconds || format == TimeFormat::kEpochMillis ||
         format == TimeFormat::kEpochMicros || format == TimeFormat::kEpochNanos;
}

std::optional<std::int64_t> parse_count(std::string_view text) {
  const std::string_view s = detail::trim(text);
  std::int64_t value = 0;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (s.empty() || ec != std::errc() || ptr != s.data() + s.size()) return std::nullopt;
  return value;
}

constexpr const char* kFormsHint =
    "time stamps are seconds, epoch seconds/ms/us/ns, ISO 8601 date-times or times of day; "
    "force the form with --time-format";

}  // namespace

TimeStampReader::TimeStampReader(TimeStampOptions options, TimeColumnSpec column)
    : options_(std::move(options)), column_(std::move(column)) {
  options_.validate();
  if (!options_.date.empty()) date_days_ = parse_date_days(options_.date);
}

InputLocation TimeStampReader::where(std::size_t line) const {
  InputLocation at;
  at.file = column_.file;
  at.line = line;
  at.column = column_.field + 1;
  at.column_name = column_.column;
  return at;
}

void TimeStampReader::bad_cell(std::string_view cell, std::size_t line, std::string_view what,
                               std::string hint) const {
  const std::string text(detail::trim(cell));
  if (text.empty()) {
    throw InputError(where(line), "the time cell is blank",
                     "every row needs a time; remove the row or fill in its time");
  }
  throw InputError(where(line), fmt::format("'{}' is not {}", text, what), std::move(hint));
}

void TimeStampReader::start(std::span<const std::string_view> first_cells,
                            std::span<const std::size_t> lines) {
  const std::size_t first_line = lines.empty() ? 0 : lines.front();
  const TimeFormat forced = options_.format;
  if (column_.has_nsec && forced != TimeFormat::kAuto && forced != TimeFormat::kSecNsec) {
    throw InputError::for_option(
        "time-format",
        fmt::format("time format '{}' does not fit the time.sec and time.nsec columns",
                    time_format_name(forced)),
        "use --time-format sec-nsec (or auto), or map one time column");
  }
  if (!column_.has_nsec && forced == TimeFormat::kSecNsec) {
    throw InputError::for_option("time-format", "time format 'sec-nsec' needs two columns",
                                 "map them with --col time.sec=COLUMN --col time.nsec=COLUMN");
  }
  if (column_.has_nsec) {
    format_ = {TimeFormat::kSecNsec, false};
  } else if (forced == TimeFormat::kAuto) {
    const std::optional<TimeStampFormat> detected = detect_time_format(first_cells);
    if (!detected) {
      for (std::size_t i = 0; i < first_cells.size(); ++i) {
        if (!detail::trim(first_cells[i]).empty()) {
          bad_cell(first_cells[i], lines[i], "a time stamp", kFormsHint);
        }
      }
      bad_cell("", first_line, "", "");
    }
    format_ = *detected;
    const double epoch_unit_s = std::pow(10.0, -epoch_exponent(format_.format));
    if (!column_.declared_unit.empty() && is_epoch(format_.format) &&
        !(std::fabs(column_.declared_unit_s / epoch_unit_s - 1.0) < 1e-12)) {
      // The declared unit wins over the epoch magnitude rule: plain counts of that unit.
      info_.notes.push_back(fmt::format(
          "the time column declares its unit ({0}), so its numbers are read as {0} from any "
          "origin, not as epoch time by their size; force --time-format epoch-s (or -ms, -us, "
          "-ns) for Unix time",
          column_.declared_unit));
      format_ = {TimeFormat::kSeconds, false};
    }
  } else {
    format_ = {forced, false};
    if (forced == TimeFormat::kSeconds || forced == TimeFormat::kEpochSeconds) {
      format_.unpadded_ns = looks_like_unpadded_ns(first_cells);
    } else if (forced == TimeFormat::kIso8601) {
      format_.unpadded_ns = looks_like_unpadded_iso8601(first_cells);
    }
  }

  const TimeFormat f = format_.format;
  plain_seconds_ = f == TimeFormat::kSeconds && !format_.unpadded_ns;
  absolute_ = is_epoch(f) || f == TimeFormat::kIso8601 || f == TimeFormat::kTimeOfDay;
  if (f == TimeFormat::kSecNsec && !first_cells.empty()) {
    const std::optional<std::int64_t> sec = parse_count(first_cells.front());
    absolute_ = sec && *sec >= 1'000'000'000;  // epoch seconds, else seconds since power-on
  }
  info_.format = std::string(time_format_name(f));
  if (format_.unpadded_ns) {
    info_.format += " (unpadded nanoseconds)";
    info_.notes.push_back(fmt::format(
        "the time fractions are integer nanoseconds without leading zeros (an exporter bug: "
        "'{}' is {}); read as such, since read as decimals the time went back or, where the "
        "fraction changed length, off the logger's pace",
        f == TimeFormat::kIso8601 ? "2025/04/28 11:39:17.78903511" : "16.79441101",
        f == TimeFormat::kIso8601 ? "11:39:17.078903511" : "16.079441101 s"));
  }
  if (f == TimeFormat::kTimeOfDay && !column_.has_date && !date_days_) {
    info_.notes.push_back(
        "times of day without a date: t = 0 is the first row's time; give --date YYYY-MM-DD "
        "or map a date column (--col date=COLUMN) for calendar times");
  }
}

std::int64_t TimeStampReader::absolute_ns(const TimeCells& cells, std::size_t line) {
  const TimeFormat f = format_.format;
  const std::string_view name = time_format_name(f);
  if (f == TimeFormat::kSecNsec) {
    const std::optional<std::int64_t> sec = parse_count(cells.time);
    if (!sec) bad_cell(cells.time, line, "whole seconds", "the time.sec column holds integers");
    const std::optional<std::int64_t> nsec = parse_count(cells.nsec);
    if (!nsec || *nsec < 0 || *nsec >= kNsPerS) {
      bad_cell(cells.nsec, line, "nanoseconds (0 to 999999999) in the time.nsec column",
               "the time.nsec column holds the integer nanoseconds of the second");
    }
    std::int64_t ns = 0;
    if (__builtin_mul_overflow(*sec, kNsPerS, &ns) || __builtin_add_overflow(ns, *nsec, &ns)) {
      bad_cell(cells.time, line, "a second within 64-bit nanoseconds (years 1678 to 2261)",
               "the time.sec column holds whole seconds since power-on or since 1970");
    }
    return ns;
  }
  if (format_.unpadded_ns && f != TimeFormat::kIso8601) {
    const std::optional<std::int64_t> ns = parse_unpadded_ns(cells.time);
    if (!ns) bad_cell(cells.time, line, "seconds.nanoseconds", kFormsHint);
    return *ns;
  }
  if (is_epoch(f)) {
    const std::optional<std::int64_t> ns = parse_decimal_ns(cells.time, epoch_exponent(f));
    if (!ns) bad_cell(cells.time, line, fmt::format("a number ({})", name), kFormsHint);
    return *ns;
  }
  if (f == TimeFormat::kIso8601) {
    const std::optional<ParsedStamp> stamp =
        format_.unpadded_ns ? parse_iso8601_unpadded_ns(cells.time) : parse_iso8601(cells.time);
    if (!stamp) bad_cell(cells.time, line, "an ISO 8601 date-time", kFormsHint);
    if (!zoned_) {
      zoned_ = stamp->utc_offset_min.has_value();
      if (*zoned_) set_origin(stamp->ns, stamp->utc_offset_min);
    }
    if (*zoned_ != stamp->utc_offset_min.has_value()) {
      bad_cell(cells.time, line, "in the first row's form",
               "the file mixes time stamps with and without a time zone");
    }
    return stamp->ns + leap_seconds_ns(stamp->leap_second, line);
  }
  // Time of day on the date of --date, of the date column, or of none.
  const std::optional<std::int64_t> tod = parse_time_of_day_ns(cells.time);
  if (!tod) bad_cell(cells.time, line, "a time of day (hh:mm:ss)", kFormsHint);
  std::int64_t days = date_days_.value_or(0);
  if (column_.has_date) {
    const std::optional<std::int64_t> d = parse_date_days(cells.date);
    if (!d) {
      throw InputError(
          where(line),
          fmt::format("'{}' in the date column is not a date", detail::trim(cells.date)),
          "the date column holds YYYY-MM-DD or YYYY/MM/DD");
    }
    days = *d;
  } else {
    if (previous_tod_ns_ >= 0 && *tod < previous_tod_ns_ - kRolloverNs) ++rollover_days_;
    previous_tod_ns_ = *tod;
    days += rollover_days_;
  }
  return days * kNsPerDay + *tod;
}

std::int64_t TimeStampReader::leap_seconds_ns(bool leap_second, std::size_t line) {
  // POSIX time gives 23:59:60.5 the instant of 00:00:00.5: the rows after a leap second are
  // one second later in elapsed time than their stamps say, so the axis keeps running.
  if (leap_second && !in_leap_second_) {
    info_.notes.push_back(fmt::format(
        "a leap second (hh:59:60) at line {}: the time axis counts it, so t after it is one "
        "second more than the stamps' difference",
        line));
  }
  if (!leap_second && in_leap_second_) leap_ns_ += kNsPerS;
  in_leap_second_ = leap_second;
  return leap_ns_;
}

void TimeStampReader::set_origin(std::int64_t ns, std::optional<int> utc_offset_min) {
  if (info_.origin_ns) return;
  info_.origin_ns = ns;
  origin_ns_ = ns;
  const bool no_date = format_.format == TimeFormat::kTimeOfDay && !column_.has_date && !date_days_;
  const bool zoned = utc_offset_min.has_value();
  // A zoned origin is shown at the file's own offset, as its users read their clocks.
  std::string text = format_iso8601(ns, utc_offset_min);
  if (no_date) text = text.substr(text.find('T') + 1);
  info_.origin = text;
  if (!zoned) {
    info_.origin_zone = "local (no zone in the file)";
  } else if (*utc_offset_min == 0) {
    info_.origin_zone = "UTC";
  } else {
    info_.origin_zone = text.substr(text.size() - 6);
  }
}

double TimeStampReader::time_s(const TimeCells& cells, std::size_t line) {
  const std::int64_t ns = absolute_ns(cells, line);
  if (!absolute_) return static_cast<double>(ns) / 1e9;  // sec-nsec or unpadded: as logged
  if (!info_.origin_ns) {
    const bool utc = is_epoch(format_.format) || format_.format == TimeFormat::kSecNsec;
    set_origin(ns, utc ? std::optional<int>(0) : std::nullopt);
  }
  // Integer difference first: exact, then one rounding to double. Stamps 2^63 ns or more apart
  // (1677 and 2262) differ in doubles.
  std::int64_t since_origin_ns = 0;
  if (__builtin_sub_overflow(ns, origin_ns_, &since_origin_ns)) {
    return (static_cast<double>(ns) - static_cast<double>(origin_ns_)) / 1e9;
  }
  return static_cast<double>(since_origin_ns) / 1e9;
}

bool TimeStampReader::out_of_order(double t, std::string_view cell, std::size_t line) {
  const bool repeat = t == last_t_;
  if (repeat && options_.order != TimeOrder::kError) {
    info_.skipped.add("duplicate time");
    return false;
  }
  if (!repeat && options_.order == TimeOrder::kDropNonIncreasing) {
    info_.skipped.add("time going back");
    return false;
  }
  const std::string shown = plain_seconds_ ? fmt::format("time {} s", t)
                                           : fmt::format("time '{}' ({} s)", detail::trim(cell), t);
  const std::string form =
      plain_seconds_ ? std::string() : fmt::format(", time stamps read as {}", info_.format);
  throw InputError(where(line),
                   fmt::format("{} {} the previous row's {} s (line {}{})", shown,
                               repeat ? "repeats" : "goes back from", last_t_, last_line_, form),
                   "time must be strictly increasing; sort the log or remove the rows, or let "
                   "--time-order drop-duplicates (or drop-non-increasing) drop them");
}

TimeColumn read_time_column(std::span<const TimeCells> cells, std::span<const std::size_t> lines,
                            const TimeStampOptions& options, const TimeColumnSpec& column) {
  TimeStampReader reader(options, column);
  std::vector<std::string_view> first;
  for (std::size_t i = 0; i < cells.size() && i < kTimeDetectionRows; ++i) {
    first.push_back(cells[i].time);
  }
  reader.start(first, lines.first(first.size()));
  TimeColumn out;
  out.kept.reserve(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i) {
    double t = 0.0;
    if (reader.plain_seconds()) {
      const std::string_view text = detail::trim(cells[i].time);
      const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), t);
      if (text.empty() || ec != std::errc() || ptr != text.data() + text.size() ||
          !std::isfinite(t)) {
        throw InputError({column.file, lines[i], column.field + 1, column.column},
                         text.empty() ? std::string("the time cell is blank")
                                      : fmt::format("'{}' is not a number", text));
      }
    } else {
      t = reader.time_s(cells[i], lines[i]);
    }
    const bool keep = reader.accept(t, cells[i].time, lines[i]);
    out.kept.push_back(keep);
    if (keep) out.t_s.push_back(t);
  }
  out.info = reader.info();
  return out;
}

}  // namespace dynpos::io
