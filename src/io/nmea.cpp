#include "dynpos/io/nmea.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <variant>
#include <vector>

#include "dynpos/core/error.hpp"
#include "text_util.hpp"

namespace dynpos::io {
namespace {

constexpr double kDay_s = 86400.0;
// Times closer than this are the same epoch [s]: NMEA times have at most millisecond digits.
constexpr double kSameEpoch_s = 1e-6;

// One fix epoch as it is assembled from its sentences.
struct Epoch {
  double t_s = 0.0;
  double lat = core::kMissing, lon = core::kMissing, height = core::kMissing;
  double quality = core::kMissing, satellites = core::kMissing, hdop = core::kMissing;
  double heading = core::kMissing, rate_of_turn = core::kMissing;
  double vtg_sog = core::kMissing, vtg_cog = core::kMissing;
  double rmc_sog = core::kMissing, rmc_cog = core::kMissing;
  bool has_gga = false, has_rmc = false, has_vtg = false, has_hdt = false, has_rot = false;
};

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
  std::vector<Epoch> epochs;
  std::size_t last_epoch_line = 0;  // line of the sentence that opened the last epoch
  std::size_t gga_seen = 0;         // GGA sentences of any talker
  std::size_t gga_used = 0;         // GGA sentences that gave an epoch its fix
  long day = 0;                     // midnight rollovers so far
  std::optional<UtcDate> first_date;
  std::size_t first_date_line = 0;
  std::map<std::string, std::string> talker_of;  // sentence type → the talker used for it
  std::string line;
  std::size_t line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string_view text = detail::trim(line);
    if (text.empty()) continue;
    if (text[0] == '!') {  // encapsulated sentences (AIS "!AIVDM"): not GNSS data
      ++out.sentences;
      ++out.skipped;
      continue;
    }
    const core::InputLocation where{name, line_no, {}, {}};
    const NmeaSentence s = parse_nmea_sentence(text, where);
    ++out.sentences;
    if (std::holds_alternative<NmeaOther>(s.data)) {
      ++out.skipped;
      continue;
    }
    if (std::holds_alternative<NmeaGga>(s.data)) ++gga_seen;
    // One talker per sentence type: the first one seen (e.g. GNGGA, not also GPGGA).
    const auto [talker, inserted] = talker_of.emplace(s.type, s.talker);
    if (!inserted && talker->second != s.talker) {
      ++out.skipped;
      continue;
    }

    // Timed sentences (GGA, RMC) open a new epoch or join the current one.
    double utc_s = core::kMissing;
    if (const auto* g = std::get_if<NmeaGga>(&s.data)) utc_s = g->utc_s;
    if (const auto* r = std::get_if<NmeaRmc>(&s.data)) utc_s = r->utc_s;
    const bool timed =
        std::holds_alternative<NmeaGga>(s.data) || std::holds_alternative<NmeaRmc>(s.data);
    if (timed) {
      if (core::is_missing(utc_s)) {  // e.g. "$GPGGA,,,,,,0,…" before the first fix
        ++out.skipped;
        continue;
      }
      double t_s = utc_s + kDay_s * static_cast<double>(day);
      if (!epochs.empty() && t_s < epochs.back().t_s - kSameEpoch_s) {
        const double back_s = epochs.back().t_s - t_s;
        if (back_s > 0.5 * kDay_s) {
          ++day;  // 23:59:59 → 00:00:00: the next day
          t_s += kDay_s;
        } else {
          core::InputLocation at = where;
          at.column = 1;
          at.column_name = s.type + ".time";
          throw core::InputError(
              at,
              fmt::format("fix time {} is {:.3f} s before the epoch of line {}", s.fields[0],
                          back_s, last_epoch_line),
              "NMEA sentences must be in time order (a jump back of more than 12 h is taken as "
              "a midnight rollover); a merged or restarted log can cause this: sort it or "
              "split it");
        }
      }
      if (epochs.empty() || t_s > epochs.back().t_s + kSameEpoch_s) {
        epochs.push_back(Epoch{});
        epochs.back().t_s = t_s;
        last_epoch_line = line_no;
      }
    } else if (epochs.empty()) {  // VTG, HDT, ROT before the first timed sentence
      ++out.skipped;
      continue;
    }
    Epoch& e = epochs.back();

    if (const auto* g = std::get_if<NmeaGga>(&s.data)) {
      if (e.has_gga) {
        ++out.skipped;
        continue;
      }
      e.has_gga = true;
      ++gga_used;
      e.quality = g->quality < 0 ? core::kMissing : g->quality;
      e.satellites = g->satellites;
      e.hdop = g->hdop;
      if (g->quality != 0) {  // quality 0: no fix, whatever the position fields say
        e.lat = g->lat_rad;
        e.lon = g->lon_rad;
        e.height = g->altitude_m + g->geoid_separation_m;  // NaN if either is empty
      }
    } else if (const auto* r = std::get_if<NmeaRmc>(&s.data)) {
      if (e.has_rmc) {
        ++out.skipped;
        continue;
      }
      e.has_rmc = true;
      if (r->valid) {
        e.rmc_sog = r->sog_mps;
        e.rmc_cog = r->cog_rad;
      }
      if (r->date) {
        if (!first_date) {
          first_date = add_days(*r->date, -day);
          first_date_line = line_no;
        } else if (days_since_epoch(*r->date) - days_since_epoch(*first_date) != day) {
          core::InputLocation at = where;
          at.column = 9;
          at.column_name = "RMC.date";
          throw core::InputError(
              at,
              fmt::format("date {} does not follow from the date of line {} and the {} midnight "
                          "rollover(s) between",
                          to_iso(*r->date), first_date_line, day),
              "the log has a gap of 12 h or more or its times jump; split the file at the gap");
        }
      }
    } else if (const auto* v = std::get_if<NmeaVtg>(&s.data)) {
      if (e.has_vtg) {
        ++out.skipped;
        continue;
      }
      e.has_vtg = true;
      if (v->mode != 'N') {  // mode N: data not valid
        e.vtg_sog = v->sog_mps;
        e.vtg_cog = v->cog_rad;
      }
    } else if (const auto* h = std::get_if<NmeaHdt>(&s.data)) {
      if (e.has_hdt) {
        ++out.skipped;
        continue;
      }
      e.has_hdt = true;
      e.heading = h->heading_rad;
    } else if (const auto* rot = std::get_if<NmeaRot>(&s.data)) {
      if (e.has_rot) {
        ++out.skipped;
        continue;
      }
      e.has_rot = true;
      if (rot->valid) e.rate_of_turn = rot->rate_rad_s;
    }
  }
  if (in.bad()) {
    throw core::InputError({name, line_no, {}, {}}, "reading the file failed",
                           "check that the file is readable");
  }
  if (out.sentences == 0) {
    throw core::InputError({name, {}, {}, {}}, "the file holds no NMEA sentences",
                           "expected lines like $GPGGA,…*hh; is this the right file?");
  }
  if (gga_used == 0) {
    throw core::InputError(
        {name, {}, {}, "GGA"},
        gga_seen == 0 ? fmt::format("no GGA sentence among the {} sentences", out.sentences)
                      : fmt::format("none of the {} GGA sentences has a UTC time", gga_seen),
        "positions and heights come from GGA (fix data) at its UTC time; configure the receiver "
        "to output GGA");
  }
  if (first_date) out.date = to_iso(*first_date);

  std::vector<double> time_s;
  time_s.reserve(epochs.size());
  for (const Epoch& e : epochs) time_s.push_back(e.t_s);
  core::Log log(std::move(time_s));
  const auto column = [&](auto member) {
    std::vector<double> values;
    values.reserve(epochs.size());
    for (const Epoch& e : epochs) values.push_back(member(e));
    return values;
  };
  log.add_channel(prefix + ".lat", "rad", column([](const Epoch& e) { return e.lat; }));
  log.add_channel(prefix + ".lon", "rad", column([](const Epoch& e) { return e.lon; }));
  log.add_channel(prefix + ".height", "m", column([](const Epoch& e) { return e.height; }));
  log.add_channel(prefix + ".quality", "1", column([](const Epoch& e) { return e.quality; }),
                  core::Interp::kNearest);
  log.add_channel(prefix + ".satellites", "1", column([](const Epoch& e) { return e.satellites; }),
                  core::Interp::kNearest);
  log.add_channel(prefix + ".hdop", "1", column([](const Epoch& e) { return e.hdop; }));
  const auto sog = column([](const Epoch& e) { return e.has_vtg ? e.vtg_sog : e.rmc_sog; });
  const auto cog = column([](const Epoch& e) { return e.has_vtg ? e.vtg_cog : e.rmc_cog; });
  const bool has_speed = std::any_of(epochs.begin(), epochs.end(),
                                     [](const Epoch& e) { return e.has_vtg || e.has_rmc; });
  if (has_speed) {
    log.add_channel(prefix + ".sog", "m/s", sog);
    log.add_channel(prefix + ".cog", "rad", cog);
  }
  const auto heading = column([](const Epoch& e) { return e.heading; });
  if (std::any_of(epochs.begin(), epochs.end(), [](const Epoch& e) { return e.has_hdt; })) {
    log.add_channel("heading", "rad", heading);
  }
  const auto rot = column([](const Epoch& e) { return e.rate_of_turn; });
  if (std::any_of(epochs.begin(), epochs.end(), [](const Epoch& e) { return e.has_rot; })) {
    log.add_channel("rate_of_turn", "rad/s", rot);
  }
  out.log = std::move(log);
  return out;
}

}  // namespace dynpos::io
