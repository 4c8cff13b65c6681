#include "dynpos/io/nmea_epoch_assembler.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <variant>

namespace dynpos::io {
namespace {

constexpr double kDay_s = 86400.0;
// Times closer than this are the same epoch [s]: NMEA times have at most millisecond digits.
constexpr double kSameEpoch_s = 1e-6;

// Each merge takes the first sentence of its type in the epoch; false for a later one.
bool merge(NmeaEpoch& e, const NmeaGga& g) {
  if (e.has_gga) return false;
  e.has_gga = true;
  e.quality = g.quality < 0 ? core::kMissing : g.quality;
  e.satellites = g.satellites;
  e.hdop = g.hdop;
  if (g.quality != 0) {  // quality 0: no fix, whatever the position fields say
    e.lat = g.lat_rad;
    e.lon = g.lon_rad;
    e.height = g.altitude_m + g.geoid_separation_m;  // NaN if either is empty
  }
  return true;
}

bool merge(NmeaEpoch& e, const NmeaRmc& r) {
  if (e.has_rmc) return false;
  e.has_rmc = true;
  if (r.valid) {
    e.rmc_sog = r.sog_mps;
    e.rmc_cog = r.cog_rad;
  }
  return true;
}

bool merge(NmeaEpoch& e, const NmeaVtg& v) {
  if (e.has_vtg) return false;
  e.has_vtg = true;
  if (v.mode != 'N') {  // mode N: data not valid
    e.vtg_sog = v.sog_mps;
    e.vtg_cog = v.cog_rad;
  }
  return true;
}

bool merge(NmeaEpoch& e, const NmeaHdt& h) {
  if (e.has_hdt) return false;
  e.has_hdt = true;
  e.heading = h.heading_rad;
  return true;
}

bool merge(NmeaEpoch& e, const NmeaRot& rot) {
  if (e.has_rot) return false;
  e.has_rot = true;
  if (rot.valid) e.rate_of_turn = rot.rate_rad_s;
  return true;
}

// Types the GNSS epochs do not use (NmeaOther, ZDA, GLL, THS, HDG, PSXN).
bool merge(NmeaEpoch&, const auto&) { return false; }

}  // namespace

bool NmeaEpochAssembler::add(const NmeaSentence& s, std::size_t line) {
  if (std::holds_alternative<NmeaOther>(s.data)) return false;
  if (std::holds_alternative<NmeaGga>(s.data)) ++gga_seen_;
  // One talker per sentence type: the first one seen (e.g. GNGGA, not also GPGGA).
  const auto [talker, inserted] = talker_of_.emplace(s.type, s.talker);
  if (!inserted && talker->second != s.talker) return false;

  // Timed sentences (GGA, RMC) open a new epoch or join the current one.
  double utc_s = core::kMissing;
  if (const auto* g = std::get_if<NmeaGga>(&s.data)) utc_s = g->utc_s;
  if (const auto* r = std::get_if<NmeaRmc>(&s.data)) utc_s = r->utc_s;
  const bool timed =
      std::holds_alternative<NmeaGga>(s.data) || std::holds_alternative<NmeaRmc>(s.data);
  if (timed && core::is_missing(utc_s)) return false;  // e.g. "$GPGGA,,,,,,0,…" before a fix
  if (!timed && epochs_.empty()) return false;  // VTG, HDT, ROT before the first timed sentence
  NmeaEpoch& e = timed ? epoch_at(utc_s, s, line) : epochs_.back();

  const bool used = std::visit([&e](const auto& data) { return merge(e, data); }, s.data);
  if (!used) return false;
  if (std::holds_alternative<NmeaGga>(s.data)) ++gga_used_;
  if (const auto* r = std::get_if<NmeaRmc>(&s.data); r != nullptr && r->date) {
    merge_rmc_date(*r->date, line);
  }
  return true;
}

NmeaEpoch& NmeaEpochAssembler::epoch_at(double utc_s, const NmeaSentence& s, std::size_t line) {
  double t_s = utc_s + kDay_s * static_cast<double>(day_);
  if (!epochs_.empty() && t_s < epochs_.back().t_s - kSameEpoch_s) {
    const double back_s = epochs_.back().t_s - t_s;
    if (back_s > 0.5 * kDay_s) {
      ++day_;  // 23:59:59 → 00:00:00: the next day
      t_s += kDay_s;
    } else {
      throw core::InputError(
          {file_, line, 1, s.type + ".time"},
          fmt::format("fix time {} is {:.3f} s before the epoch of line {}", s.fields[0], back_s,
                      last_epoch_line_),
          "NMEA sentences must be in time order (a jump back of more than 12 h is taken as "
          "a midnight rollover); a merged or restarted log can cause this: sort it or "
          "split it");
    }
  }
  if (epochs_.empty() || t_s > epochs_.back().t_s + kSameEpoch_s) {
    epochs_.push_back(NmeaEpoch{});
    epochs_.back().t_s = t_s;
    last_epoch_line_ = line;
  }
  return epochs_.back();
}

void NmeaEpochAssembler::merge_rmc_date(const UtcDate& date, std::size_t line) {
  if (!first_date_) {
    first_date_ = add_days(date, -day_);
    first_date_line_ = line;
  } else if (days_since_epoch(date) - days_since_epoch(*first_date_) != day_) {
    throw core::InputError(
        {file_, line, 9, "RMC.date"},
        fmt::format("date {} does not follow from the date of line {} and the {} midnight "
                    "rollover(s) between",
                    to_iso(date), first_date_line_, day_),
        "the log has a gap of 12 h or more or its times jump; split the file at the gap");
  }
}

core::Log nmea_epochs_to_log(const std::vector<NmeaEpoch>& epochs, const std::string& prefix) {
  std::vector<double> time_s;
  time_s.reserve(epochs.size());
  for (const NmeaEpoch& e : epochs) time_s.push_back(e.t_s);
  core::Log log(std::move(time_s));
  const auto column = [&](auto member) {
    std::vector<double> values;
    values.reserve(epochs.size());
    for (const NmeaEpoch& e : epochs) values.push_back(member(e));
    return values;
  };
  const auto any = [&](auto has) { return std::any_of(epochs.begin(), epochs.end(), has); };
  log.add_channel(prefix + ".lat", "rad", column([](const NmeaEpoch& e) { return e.lat; }));
  log.add_channel(prefix + ".lon", "rad", column([](const NmeaEpoch& e) { return e.lon; }));
  log.add_channel(prefix + ".height", "m", column([](const NmeaEpoch& e) { return e.height; }));
  log.add_channel(prefix + ".quality", "1", column([](const NmeaEpoch& e) { return e.quality; }),
                  core::Interp::kNearest);
  log.add_channel(prefix + ".satellites", "1",
                  column([](const NmeaEpoch& e) { return e.satellites; }), core::Interp::kNearest);
  log.add_channel(prefix + ".hdop", "1", column([](const NmeaEpoch& e) { return e.hdop; }));
  if (any([](const NmeaEpoch& e) { return e.has_vtg || e.has_rmc; })) {
    log.add_channel(prefix + ".sog", "m/s",
                    column([](const NmeaEpoch& e) { return e.has_vtg ? e.vtg_sog : e.rmc_sog; }));
    log.add_channel(prefix + ".cog", "rad",
                    column([](const NmeaEpoch& e) { return e.has_vtg ? e.vtg_cog : e.rmc_cog; }));
  }
  if (any([](const NmeaEpoch& e) { return e.has_hdt; })) {
    log.add_channel("heading", "rad", column([](const NmeaEpoch& e) { return e.heading; }));
  }
  if (any([](const NmeaEpoch& e) { return e.has_rot; })) {
    log.add_channel("rate_of_turn", "rad/s",
                    column([](const NmeaEpoch& e) { return e.rate_of_turn; }));
  }
  return log;
}

}  // namespace dynpos::io
