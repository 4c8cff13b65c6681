#include "dynpos/io/nmea_log.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <variant>
#include <vector>

#include "capture_lines.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/io/nmea_sentence.hpp"
#include "logger_stamp.hpp"
#include "text_util.hpp"

namespace dynpos::io {
namespace {

using detail::kDay_ns;

enum Role { kLat, kLon, kHeight, kHeading, kRoll, kPitch, kDown, kR, kRoleCount };
constexpr std::array<const char*, kRoleCount> kRoleName = {"lat",  "lon",   "height", "heading",
                                                           "roll", "pitch", "down",   "r"};
constexpr std::array<const char*, kRoleCount> kRoleUnit = {"rad", "rad", "m", "rad",
                                                           "rad", "rad", "m", "rad/s"};

enum Source { kGga, kRmc, kGll, kHdt, kThs, kPsxn23, kHdg, kRot, kSourceCount };
constexpr std::array<const char*, kSourceCount> kSourceName = {"GGA", "RMC",     "GLL", "HDT",
                                                               "THS", "PSXN,23", "HDG", "ROT"};

// The sources of each role, best first: the first one the capture has gives the role.
const std::vector<Source>& sources_of(Role role) {
  static const std::array<std::vector<Source>, kRoleCount> kSources = {{
      {kGga, kRmc, kGll},           // lat
      {kGga, kRmc, kGll},           // lon
      {kGga},                       // height
      {kHdt, kThs, kPsxn23, kHdg},  // heading
      {kPsxn23},                    // roll
      {kPsxn23},                    // pitch
      {kPsxn23},                    // down (heave)
      {kRot},                       // r
  }};
  return kSources[role];
}

struct Sample {
  std::int64_t t_ns;  // on the capture's clock (see CaptureReader::Clock)
  double value;
};

// One line: the sentence and the logger stamp before it, or the kind it is skipped as.
struct LineScan {
  std::string skip;
  std::string_view sentence;
  std::optional<detail::LoggerStamp> stamp;
};

bool is_hex(char c) { return (c >= '0' && c <= '9') || (c >= 'A' && c <= 'F'); }

// Splits a non-blank line; `cut` says the file ended inside this line (no line end after it).
LineScan scan_line(std::string_view text, bool cut) {
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if ((u < 0x20 && c != '\t') || u >= 0x7f) return {"binary", {}, {}};
  }
  const std::size_t start = text.find_first_of("$!");
  if (start == std::string_view::npos) {
    // The tail of a sentence whose start was cut off ("…,M,,*47"), else a comment or header.
    const bool tail = text.find(',') != std::string_view::npos && text.size() >= 3 &&
                      text[text.size() - 3] == '*' && is_hex(text[text.size() - 2]) &&
                      is_hex(text.back());
    return {tail ? "truncated" : "comment", {}, {}};
  }
  LineScan out;
  out.sentence = text.substr(start);
  if (out.sentence[0] == '!') return {"unknown sentence", {}, {}};  // AIS and other encapsulated
  // A sentence cut off and followed by the next one on the same line.
  if (out.sentence.find('$', 1) != std::string_view::npos) return {"truncated", {}, {}};
  if (cut && out.sentence.find('*') == std::string_view::npos) return {"truncated", {}, {}};
  const std::string_view prefix = detail::trim(text.substr(0, start));
  if (!prefix.empty()) {
    out.stamp = detail::find_logger_stamp(prefix);
    if (!out.stamp) {
      out.skip =
          prefix.find_first_of(",*") != std::string_view::npos ? "truncated" : "bad time stamp";
    }
  }
  return out;
}

// The kind a sentence the parser rejects is skipped as.
std::string parse_failure_kind(const core::InputError& e, std::string_view sentence) {
  if (e.where().column_name == "checksum") return "bad checksum";
  const bool short_form =
      e.where().column_name == "address" || e.where().column_name.ends_with(".field_count");
  if (short_form && sentence.find('*') == std::string_view::npos) return "truncated";
  return "bad field";
}

// Reads the lines of one capture in order and assembles its samples.
class CaptureReader {
 public:
  CaptureReader(std::string file, const NmeaLogOptions& options)
      : file_(std::move(file)), options_(options) {}

  void add_line(std::string_view text, std::size_t line, bool cut);
  /// A line longer than kMaxNmeaLineBytes (its first bytes are not read as a sentence).
  void too_long(std::size_t line) {
    skip("too long", line, fmt::format("more than {} bytes", kMaxNmeaLineBytes));
  }
  NmeaLog finish();
  /// Lines read as a valid sentence (address and fields) that show the file is a capture: with
  /// its checksum, or of a type the reader knows. One without either ("$P,1" is a proprietary
  /// sentence) is what random bytes give about once in 2·10⁷ lines: /dev/urandom would then be
  /// read for ever.
  std::size_t sentences() const noexcept { return sentences_; }

 private:
  enum class Clock { kUnknown, kLogger, kUtc };

  void skip(std::string_view kind, std::size_t line, const std::string& detail = {});
  void use(const NmeaSentence& s, std::optional<detail::LoggerStamp> stamp, std::size_t line);
  std::optional<std::int64_t> utc_time(const NmeaSentence& s, std::size_t line);
  void take_values(const NmeaSentence& s, std::int64_t t_ns);
  void take_date(const std::optional<UtcDate>& date, std::int64_t t_ns);
  void record(Role role, Source source, std::int64_t t_ns, double value) {
    if (std::isfinite(value)) samples_[role][source].push_back({t_ns, value});
  }
  std::string roles_note(const std::array<int, kRoleCount>& chosen) const;
  NmeaLog build(const std::array<int, kRoleCount>& chosen);

  std::string file_;
  const NmeaLogOptions& options_;
  FileReport report_;
  Clock clock_ = Clock::kUnknown;
  std::string stamp_form_;
  std::array<std::array<std::vector<Sample>, kSourceCount>, kRoleCount> samples_;
  std::map<std::string, std::string> talker_of_;  // sentence type → the talker used for it
  // UTC clock: midnight rollovers so far, latest time [ns since 00:00 of day 0], current epoch
  // and the sentence types used in it; the date of day 0.
  std::int64_t day_ = 0;
  std::optional<std::int64_t> latest_ns_, epoch_ns_;
  std::set<std::string> epoch_types_;
  std::optional<UtcDate> day0_;
  NmeaPsxnQuality seapath_quality_;  // the last PSXN,20
  bool hdg_without_variation_ = false;
  bool epoch_back_ = false;  // the last timed sentence stepped back: its epoch is dropped
  std::size_t sentences_ = 0;
};

void CaptureReader::skip(std::string_view kind, std::size_t line, const std::string& detail) {
  report_.skipped.add(kind);
  if (options_.strict) {
    throw core::InputError(
        {file_, line, {}, {}},
        fmt::format("line not usable ({}){}", kind, detail.empty() ? "" : ": " + detail),
        "strict reading stops at the first line it cannot use; without "
        "--strict such lines are skipped and counted in the report");
  }
}

void CaptureReader::add_line(std::string_view text, std::size_t line, bool cut) {
  const LineScan scan = scan_line(text, cut);
  if (!scan.skip.empty()) return skip(scan.skip, line);
  NmeaSentence s;
  try {
    s = parse_nmea_sentence(scan.sentence, {file_, line, {}, {}}, {.lenient_field_count = true});
  } catch (const core::InputError& e) {
    if (options_.strict) throw;
    return skip(parse_failure_kind(e, scan.sentence), line);
  }
  const bool other = std::holds_alternative<NmeaOther>(s.data);
  if (s.has_checksum || !other) ++sentences_;
  if (other) {
    return skip("unknown sentence", line, s.talker + s.type);
  }
  if (!s.has_checksum) report_.accepted.add("no checksum");
  use(s, scan.stamp, line);
}

// "HH:MM:SS.sss" of a time on the UTC clock.
std::string clock_text(std::int64_t t_ns) {
  const std::int64_t ms = t_ns % kDay_ns / 1'000'000;
  return fmt::format("{:02d}:{:02d}:{:02d}.{:03d}", ms / 3'600'000, ms / 60'000 % 60,
                     ms / 1000 % 60, ms % 1000);
}

// The time of a GGA, RMC, GLL or ZDA on the UTC clock [ns since 00:00 of day 0], nullopt for
// other types; a time more than 12 h before the latest is the next day. A time less far back
// (a second receiver's clock, a clock reset) is not sorted in among the others: the sentence
// is skipped and counted as "time back", with the untimed sentences of its epoch.
std::optional<std::int64_t> CaptureReader::utc_time(const NmeaSentence& s, std::size_t line) {
  double utc_s = core::kMissing;
  bool timed = true;
  if (const auto* g = std::get_if<NmeaGga>(&s.data)) {
    utc_s = g->utc_s;
  } else if (const auto* r = std::get_if<NmeaRmc>(&s.data)) {
    utc_s = r->utc_s;
  } else if (const auto* l = std::get_if<NmeaGll>(&s.data)) {
    utc_s = l->utc_s;
  } else if (const auto* z = std::get_if<NmeaZda>(&s.data)) {
    utc_s = z->utc_s;
  } else {
    timed = false;
  }
  if (!timed) return std::nullopt;
  if (core::is_missing(utc_s)) {
    skip("no time", line, s.type + " with an empty UTC field");
    return std::nullopt;
  }
  std::int64_t t = std::llround(utc_s * 1e9) + day_ * kDay_ns;
  if (latest_ns_ && t < *latest_ns_ - kDay_ns / 2) {
    ++day_;  // 23:59:59 → 00:00:00
    t += kDay_ns;
  }
  epoch_back_ = latest_ns_ && t < *latest_ns_;
  if (epoch_back_) {
    skip("time back", line,
         fmt::format("{} at {} after {}", s.type, clock_text(t), clock_text(*latest_ns_)));
    return std::nullopt;
  }
  latest_ns_ = t;
  return t;
}

void CaptureReader::use(const NmeaSentence& s, std::optional<detail::LoggerStamp> stamp,
                        std::size_t line) {
  if (clock_ == Clock::kUnknown) {
    clock_ = stamp ? Clock::kLogger : Clock::kUtc;
    if (stamp) {
      stamp_form_ = stamp->form;
      if (!stamp->zone_given)
        report_.notes.push_back("logger time stamps without a zone: read as UTC");
    }
  }
  // One talker per sentence type, the first one seen (GNGGA, not also GPGGA).
  const auto [talker, inserted] = talker_of_.emplace(s.type, s.talker);
  if (!inserted && talker->second != s.talker) {
    return skip("other talker", line,
                fmt::format("{}{} after {}{}", s.talker, s.type, talker->second, s.type));
  }
  std::int64_t t_ns = 0;
  if (clock_ == Clock::kLogger) {
    if (!stamp) return skip("no time stamp", line);
    t_ns = stamp->unix_ns;
  } else {
    const bool timed =
        std::holds_alternative<NmeaGga>(s.data) || std::holds_alternative<NmeaRmc>(s.data) ||
        std::holds_alternative<NmeaGll>(s.data) || std::holds_alternative<NmeaZda>(s.data);
    if (timed) {
      const std::optional<std::int64_t> t = utc_time(s, line);
      if (!t) return;  // counted by utc_time
      if (t != epoch_ns_) epoch_types_.clear();
      epoch_ns_ = t;
    } else if (!epoch_ns_) {
      return skip("no time", line, s.type + " before the first sentence with a UTC time");
    } else if (epoch_back_) {
      return skip("time back", line, s.type + " after a time that stepped back");
    }
    // Untimed sentences take the epoch's time: one of each type per epoch.
    if (!epoch_types_.insert(s.type).second) return skip("repeat in epoch", line, s.type);
    t_ns = *epoch_ns_;
  }
  ++report_.records;
  take_values(s, t_ns);
}

void CaptureReader::take_date(const std::optional<UtcDate>& date, std::int64_t t_ns) {
  if (clock_ != Clock::kUtc || !date || day0_) return;
  day0_ = add_days(*date, -static_cast<long>(t_ns / kDay_ns));
}

void CaptureReader::take_values(const NmeaSentence& s, std::int64_t t) {
  if (const auto* g = std::get_if<NmeaGga>(&s.data)) {
    if (g->quality == 0) return report_.accepted.add("no fix");
    record(kLat, kGga, t, g->lat_rad);
    record(kLon, kGga, t, g->lon_rad);
    double separation = g->geoid_separation_m;
    if (core::is_missing(separation) && !core::is_missing(g->altitude_m)) {
      report_.accepted.add("empty geoid separation");
      separation = 0.0;
    }
    record(kHeight, kGga, t, g->altitude_m + separation);
  } else if (const auto* r = std::get_if<NmeaRmc>(&s.data)) {
    take_date(r->date, t);
    if (!r->valid) return report_.accepted.add("no fix");
    record(kLat, kRmc, t, r->lat_rad);
    record(kLon, kRmc, t, r->lon_rad);
  } else if (const auto* l = std::get_if<NmeaGll>(&s.data)) {
    if (!l->valid) return report_.accepted.add("no fix");
    record(kLat, kGll, t, l->lat_rad);
    record(kLon, kGll, t, l->lon_rad);
  } else if (const auto* z = std::get_if<NmeaZda>(&s.data)) {
    take_date(z->date, t);
  } else if (const auto* h = std::get_if<NmeaHdt>(&s.data)) {
    record(kHeading, kHdt, t, h->heading_rad);
  } else if (const auto* ths = std::get_if<NmeaThs>(&s.data)) {
    if (ths->mode != 'V') record(kHeading, kThs, t, ths->heading_rad);
  } else if (const auto* hdg = std::get_if<NmeaHdg>(&s.data)) {
    // True = magnetic sensor + deviation + variation (east +); an empty one counts as 0.
    const double deviation = std::isfinite(hdg->deviation_rad) ? hdg->deviation_rad : 0.0;
    hdg_without_variation_ = hdg_without_variation_ || !std::isfinite(hdg->variation_rad);
    const double variation = std::isfinite(hdg->variation_rad) ? hdg->variation_rad : 0.0;
    record(kHeading, kHdg, t, hdg->sensor_heading_rad + deviation + variation);
  } else if (const auto* rot = std::get_if<NmeaRot>(&s.data)) {
    if (rot->valid) record(kR, kRot, t, rot->rate_rad_s);
  } else if (const auto* q = std::get_if<NmeaPsxnQuality>(&s.data)) {
    seapath_quality_ = *q;
  } else if (const auto* a = std::get_if<NmeaPsxnAttitude>(&s.data)) {
    // Seapath quality 2 (invalid) in the last PSXN,20 drops the values it flags.
    if (seapath_quality_.heading != 2) record(kHeading, kPsxn23, t, a->heading_rad);
    if (seapath_quality_.roll_pitch != 2) {
      record(kRoll, kPsxn23, t, a->roll_rad);
      record(kPitch, kPsxn23, t, a->pitch_rad);
    }
    if (seapath_quality_.height != 2) record(kDown, kPsxn23, t, a->heave_m);
  }
}

std::string CaptureReader::roles_note(const std::array<int, kRoleCount>& chosen) const {
  std::string out;
  for (int role = 0; role < kRoleCount; ++role) {
    if (chosen[role] < 0) continue;
    out += fmt::format("{}{} from {}", out.empty() ? "roles: " : ", ", kRoleName[role],
                       kSourceName[chosen[role]]);
  }
  return out;
}

NmeaLog CaptureReader::finish() {
  // Per role the first source with samples.
  std::array<int, kRoleCount> chosen;
  chosen.fill(-1);
  for (int role = 0; role < kRoleCount; ++role) {
    for (const Source source : sources_of(static_cast<Role>(role))) {
      if (!samples_[role][source].empty()) {
        chosen[role] = source;
        break;
      }
    }
  }
  if (std::all_of(chosen.begin(), chosen.end(), [](int c) { return c < 0; })) {
    std::string found;
    for (const auto& [kind, n] : report_.skipped.by_kind()) {
      found += fmt::format("{}{} {}", found.empty() ? "" : ", ", n, kind);
    }
    throw core::InputError(
        {file_, {}, {}, {}},
        fmt::format("no usable NMEA sentence: {} sentences used, none with a position, heading, "
                    "attitude or rate; skipped: {}",
                    report_.records, found.empty() ? "none" : found),
        "the capture needs GGA, RMC or GLL (position), HDT, THS, HDG or PSXN,23 (heading, "
        "attitude) or ROT (rate of turn), one sentence a line; is this the right file?");
  }
  if (chosen[kHeight] >= 0 && report_.accepted.count("empty geoid separation") > 0) {
    report_.notes.push_back(
        "GGA with an empty geoid separation (as Seapath 200 and OxTS write it): height = "
        "altitude, the separation taken as 0");
  }
  if (chosen[kHeading] == kHdg) {
    report_.notes.push_back(hdg_without_variation_
                                ? "heading from HDG: magnetic; some sentences have no variation, "
                                  "so those headings are magnetic, not true"
                                : "heading from HDG: magnetic sensor + deviation + variation");
  }
  return build(chosen);
}

// The chosen samples of the wanted channels on the union of their times.
NmeaLog CaptureReader::build(const std::array<int, kRoleCount>& chosen) {
  struct Column {
    std::string name;
    Role role;
    std::vector<Sample> samples;
  };
  std::vector<Column> columns;
  std::vector<std::int64_t> times;
  for (int role = 0; role < kRoleCount; ++role) {
    if (chosen[role] < 0) continue;
    std::string name =
        options_.prefix.empty() ? kRoleName[role] : options_.prefix + "." + kRoleName[role];
    if (options_.wanted && !options_.wanted(name)) continue;
    std::vector<Sample>& samples = samples_[role][chosen[role]];
    std::stable_sort(samples.begin(), samples.end(),
                     [](const Sample& a, const Sample& b) { return a.t_ns < b.t_ns; });
    for (const Sample& x : samples) times.push_back(x.t_ns);
    columns.push_back({std::move(name), static_cast<Role>(role), std::move(samples)});
  }
  std::array<int, kRoleCount> kept;
  kept.fill(-1);
  for (const Column& c : columns) kept[c.role] = chosen[c.role];
  if (!columns.empty()) report_.notes.insert(report_.notes.begin(), roles_note(kept));
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());

  NmeaLog out;
  std::vector<double> t_s(times.size());
  for (std::size_t i = 0; i < times.size(); ++i)
    t_s[i] = 1e-9 * static_cast<double>(times[i] - times[0]);
  out.log = core::Log(std::move(t_s));
  for (Column& c : columns) {
    std::vector<double> values(times.size(), core::kMissing);
    for (const Sample& x : c.samples) {
      const auto row = std::lower_bound(times.begin(), times.end(), x.t_ns) - times.begin();
      // Two samples at one time: the first in the file.
      if (core::is_missing(values[row])) values[row] = x.value;
    }
    out.log.add_channel(c.name, kRoleUnit[c.role], std::move(values));
  }
  report_.format = "nmea";
  report_.path = file_;
  if (clock_ == Clock::kLogger) {
    report_.time_format = stamp_form_ + " (logger)";
    if (!times.empty()) out.origin_ns = times.front();
  } else {
    report_.time_format = "nmea utc";
    if (!times.empty() && day0_) {
      out.origin_ns = days_since_epoch(*day0_) * kDay_ns + times.front();
    } else if (!times.empty()) {
      const std::int64_t s = times.front() % kDay_ns / 1'000'000'000;
      report_.notes.push_back(
          fmt::format("no date (ZDA or RMC): t = 0 s is {:02d}:{:02d}:{:02d} "
                      "UTC of an unknown day",
                      s / 3600, s / 60 % 60, s % 60));
    }
  }
  if (out.origin_ns) out.origin = detail::iso8601_utc(*out.origin_ns);
  out.report = std::move(report_);
  return out;
}

// Counts the sentence-like lines among the first non-blank ones.
bool sentence_like(std::string_view text) {
  const std::size_t start = text.find_first_of("$!");
  if (start == std::string_view::npos) return false;
  std::size_t k = start + 1;
  while (k < text.size() &&
         ((text[k] >= 'A' && text[k] <= 'Z') || (text[k] >= '0' && text[k] <= '9')))
    ++k;
  return k - start - 1 >= 4 && k < text.size() && text[k] == ',';
}

// How far a capture has been read: its lines and its bytes.
struct ReadSoFar {
  std::size_t lines;
  std::uint64_t bytes;
};

// A capture without a valid sentence in its first kMaxNmeaLinesWithoutSentence lines or
// kMaxNmeaBytesWithoutSentence bytes is not one: refused, not read to an end that may not come.
void give_up_without_sentence(const std::string& file, ReadSoFar read) {
  const std::size_t line = read.lines;
  const bool by_lines = line >= kMaxNmeaLinesWithoutSentence;
  if (!by_lines && read.bytes < kMaxNmeaBytesWithoutSentence) return;
  throw core::InputError(
      {file, line, {}, {}},
      fmt::format("not an NMEA capture: no valid NMEA sentence in the first {}",
                  by_lines ? fmt::format("{} lines", line)
                           : fmt::format("{} MiB", kMaxNmeaBytesWithoutSentence >> 20)),
      "give a capture of NMEA 0183 sentences ($GPGGA,…*hh), one a line; is this the right "
      "file?");
}

}  // namespace

NmeaLog read_nmea_log(const std::filesystem::path& file, const NmeaLogOptions& options) {
  const std::string name = file.string();
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    throw core::InputError({name, {}, {}, {}}, "cannot open the NMEA capture",
                           "check the path and the file's permissions");
  }
  CaptureReader reader(name, options);
  detail::CaptureLines lines(in);
  std::string line;
  std::size_t line_no = 0;
  for (;;) {
    const detail::LineStatus status = lines.next(line, kMaxNmeaLineBytes);
    if (status == detail::LineStatus::kEnd || lines.bad()) break;
    ++line_no;
    if (status == detail::LineStatus::kTooLong) {
      reader.too_long(line_no);
      if (!lines.skip_rest(kMaxNmeaJunkBytes)) {
        detail::throw_no_line_end(name, line_no, kMaxNmeaJunkBytes);
      }
    } else if (const std::string_view text = detail::trim(line); !text.empty()) {
      // Not ended: the file ends inside this line, with no line end after it.
      reader.add_line(text, line_no, !lines.ended());
    }
    if (reader.sentences() == 0)
      give_up_without_sentence(name, {.lines = line_no, .bytes = lines.bytes()});
  }
  if (in.bad()) {
    throw core::InputError({name, line_no, {}, {}}, "reading the file failed",
                           "check that the file is readable");
  }
  return reader.finish();
}

bool looks_like_nmea(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  detail::CaptureLines capture(in);
  std::string line;
  std::size_t lines = 0, sentences = 0;
  while (lines < 200) {
    const detail::LineStatus status = capture.next(line, kMaxNmeaLineBytes);
    if (status == detail::LineStatus::kEnd || capture.bad()) break;
    if (status == detail::LineStatus::kTooLong) {
      ++lines;  // not a sentence; without a line end not a text capture
      if (!capture.skip_rest(kMaxNmeaJunkBytes)) break;
      continue;
    }
    const std::string_view text = detail::trim(line);
    if (text.empty()) continue;
    ++lines;
    if (sentence_like(text)) ++sentences;
  }
  return 2 * sentences > lines;
}

}  // namespace dynpos::io
