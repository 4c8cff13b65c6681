#include "dynpos/io/nmea.hpp"

#include <fmt/core.h>

#include <fstream>

#include "capture_lines.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/io/nmea_epoch_assembler.hpp"
#include "dynpos/io/nmea_log.hpp"
#include "text_util.hpp"

namespace dynpos::io {
namespace {

// Parses "HH:MM:SS[.sss]" at text[pos…]; advances pos.
double parse_clock(const std::string& text, std::size_t& pos, const auto& bad) {
  const auto two = [&](std::size_t at) {
    if (at + 2 > text.size() || text[at] < '0' || text[at] > '9' || text[at + 1] < '0' ||
        text[at + 1] > '9') {
      bad();
    }
    return (text[at] - '0') * 10 + (text[at + 1] - '0');
  };
  const int hh = two(pos);
  if (pos + 2 >= text.size() || text[pos + 2] != ':') bad();
  const int mm = two(pos + 3);
  if (pos + 5 >= text.size() || text[pos + 5] != ':') bad();
  double ss = two(pos + 6);
  pos += 8;
  if (pos < text.size() && text[pos] == '.') {
    ++pos;
    double scale = 0.1;
    const std::size_t first = pos;
    for (; pos < text.size() && text[pos] >= '0' && text[pos] <= '9'; ++pos, scale /= 10.0) {
      ss += (text[pos] - '0') * scale;
    }
    if (pos == first) bad();
  }
  // A leap second (second 60) is allowed; it reads as the first instant of the next minute.
  if (hh > 23 || mm > 59 || ss >= 61.0) bad();
  return hh * 3600.0 + mm * 60.0 + ss;
}

// The sentence, or nullopt for one of a type the epochs do not use (ZDA, GLL, PSXN, …) whose
// fields are malformed: it would be skipped anyway. A bad checksum or address is an error.
std::optional<NmeaSentence> parse_for_epochs(std::string_view text,
                                             const core::InputLocation& where) {
  try {
    return parse_nmea_sentence(text, where);
  } catch (const core::InputError& e) {
    const std::string& field = e.where().column_name;
    const std::string type = field.substr(0, field.find('.'));
    const bool used = type == "GGA" || type == "RMC" || type == "VTG" || type == "HDT" ||
                      type == "ROT" || field.find('.') == std::string::npos;
    if (used) throw;
    return std::nullopt;
  }
}

}  // namespace

UtcTimestamp parse_utc_timestamp(const std::string& text) {
  const auto bad = [&]() {
    throw core::InputError({{}, {}, {}, "time"}, fmt::format("'{}' is not a UTC time", text),
                           "write HH:MM:SS[.sss] or YYYY-MM-DDTHH:MM:SS[.sss]Z, e.g. "
                           "2014-08-27T10:00:00Z (hours 00-23, UTC)");
  };
  UtcTimestamp out;
  std::size_t pos = 0;
  if (text.size() >= 11 && text[4] == '-' && text[7] == '-' && text[10] == 'T') {
    UtcDate d;
    int value[3] = {0, 0, 0};
    const std::size_t starts[3] = {0, 5, 8}, lengths[3] = {4, 2, 2};
    for (int k = 0; k < 3; ++k) {
      for (std::size_t i = starts[k]; i < starts[k] + lengths[k]; ++i) {
        if (text[i] < '0' || text[i] > '9') bad();
        value[k] = value[k] * 10 + (text[i] - '0');
      }
    }
    d.year = value[0];
    d.month = value[1];
    d.day = value[2];
    if (!is_valid(d)) bad();
    out.date = d;
    pos = 11;
  }
  out.time_of_day_s = parse_clock(text, pos, bad);
  if (out.date) {
    if (pos >= text.size() || text[pos] != 'Z') bad();
    ++pos;
  }
  if (pos != text.size()) bad();
  return out;
}

double parse_utc_time_of_day(const std::string& text) {
  return parse_utc_timestamp(text).time_of_day_s;
}

NmeaGnssLog read_nmea_gnss(const std::filesystem::path& file, const std::string& prefix) {
  const std::string name = file.string();
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    throw core::InputError({name, {}, {}, {}}, "cannot open the NMEA file",
                           "check the path and the file's permissions");
  }
  NmeaGnssLog out;
  NmeaEpochAssembler epochs(name);
  detail::CaptureLines lines(in);
  std::string line;
  std::size_t line_no = 0;
  for (;;) {
    const detail::LineStatus status = lines.next(line, kMaxNmeaLineBytes);
    if (status == detail::LineStatus::kEnd || lines.bad()) break;
    ++line_no;
    if (status == detail::LineStatus::kTooLong) {
      ++out.sentences;
      ++out.skipped;
      if (!lines.skip_rest(kMaxNmeaJunkBytes)) {
        detail::throw_no_line_end(name, line_no, kMaxNmeaJunkBytes);
      }
      continue;
    }
    const std::string_view text = detail::trim(line);
    if (text.empty()) continue;
    ++out.sentences;
    if (text[0] == '!') {  // encapsulated sentences (AIS "!AIVDM"): not GNSS data
      ++out.skipped;
      continue;
    }
    const std::optional<NmeaSentence> s = parse_for_epochs(text, {name, line_no, {}, {}});
    if (!s || !epochs.add(*s, line_no)) ++out.skipped;
  }
  if (in.bad()) {
    throw core::InputError({name, line_no, {}, {}}, "reading the file failed",
                           "check that the file is readable");
  }
  if (out.sentences == 0) {
    throw core::InputError({name, {}, {}, {}}, "the file holds no NMEA sentences",
                           "expected lines like $GPGGA,…*hh; is this the right file?");
  }
  if (epochs.gga_used() == 0) {
    throw core::InputError(
        {name, {}, {}, "GGA"},
        epochs.gga_seen() == 0
            ? fmt::format("no GGA sentence among the {} sentences", out.sentences)
            : fmt::format("none of the {} GGA sentences has a UTC time", epochs.gga_seen()),
        "positions and heights come from GGA (fix data) at its UTC time; configure the receiver "
        "to output GGA");
  }
  if (epochs.date()) out.date = to_iso(*epochs.date());
  out.log = nmea_epochs_to_log(epochs.epochs(), prefix);
  return out;
}

}  // namespace dynpos::io
