#include "dynpos/scenario/device_files.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>

#include "dynpos/io/atomic_file.hpp"
#include "dynpos/io/nmea.hpp"
#include "dynpos/io/nmea_writer.hpp"
#include "dynpos/scenario/runner.hpp"
#include "dynpos/sim/random.hpp"

namespace dynpos::scenario {

// The antennas of a trial log: prefixes "gnssK" with K's lat, lon, height, north and east.
std::vector<std::string> gnss_antennas(const core::Log& log) {
  std::vector<std::string> names;
  for (const std::string& channel : log.channel_names()) {
    const std::string suffix = ".lat";
    if (channel.rfind("gnss", 0) != 0 || channel.size() <= suffix.size() ||
        channel.compare(channel.size() - suffix.size(), suffix.size(), suffix) != 0) {
      continue;
    }
    const std::string antenna = channel.substr(0, channel.size() - suffix.size());
    bool complete = true;
    for (const char* c : {".lon", ".height", ".north", ".east"}) complete &= log.has(antenna + c);
    if (complete) names.push_back(antenna);
  }
  return names;
}

// Position and height are the logged fix (GGA altitude = ellipsoidal height − geoid separation,
// with the separation in its own field); fix quality 4 (RTK fixed, as the simulated receivers'
// centimetre noise is); satellites and HDOP are not simulated, so their fields are empty.
// SOG and COG (RMC, VTG) come from the antenna's own track: the central difference of its local
// north/east over the neighbouring fixes (one-sided at the ends). HDT is the gyro compass
// ("heading"), its last sample at or before the fix time. UTC = start_utc + t.
std::vector<TimedSentence> gnss_sentences(const ScenarioRun& run, const std::string& antenna) {
  constexpr double kDegToRad = std::numbers::pi / 180.0;
  const io::UtcTimestamp start = io::parse_utc_timestamp(run.start_utc);
  if (!start.date) throw std::invalid_argument("ScenarioRun::start_utc has no date");
  const core::Log& log = run.log;
  const auto& t = log.time();
  const auto& lat = log.values(antenna + ".lat");
  const auto& lon = log.values(antenna + ".lon");
  const auto& height = log.values(antenna + ".height");
  const auto& north = log.values(antenna + ".north");
  const auto& east = log.values(antenna + ".east");
  const std::vector<double>* heading = log.has("heading") ? &log.values("heading") : nullptr;
  std::vector<std::size_t> fixes;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!core::is_missing(lat[i]) && !core::is_missing(lon[i])) fixes.push_back(i);
  }
  std::vector<TimedSentence> out;
  double last_heading_deg = core::kMissing;
  std::size_t next_heading_row = 0;
  for (std::size_t k = 0; k < fixes.size(); ++k) {
    const std::size_t i = fixes[k];
    const double utc_s = start.time_of_day_s + t[i];
    const long day = static_cast<long>(std::floor((utc_s + 0.0005) / 86400.0));
    // Track velocity [m/s] from the neighbouring fixes.
    double sog_mps = core::kMissing, cog_rad = core::kMissing;
    if (fixes.size() >= 2) {
      const std::size_t a = fixes[k == 0 ? 0 : k - 1];
      const std::size_t b = fixes[k + 1 == fixes.size() ? k : k + 1];
      const double dn = north[b] - north[a], de = east[b] - east[a], dt = t[b] - t[a];
      sog_mps = std::hypot(dn, de) / dt;
      cog_rad = std::atan2(de, dn);
    }
    io::NmeaGga gga;
    gga.utc_s = utc_s;
    gga.lat_rad = lat[i] * kDegToRad;
    gga.lon_rad = lon[i] * kDegToRad;
    gga.quality = 4;
    gga.satellites = core::kMissing;
    gga.hdop = core::kMissing;
    gga.altitude_m = height[i] - run.geoid_separation_m;
    gga.geoid_separation_m = run.geoid_separation_m;
    gga.age_s = core::kMissing;
    out.push_back({t[i], io::format_gga("GN", gga)});
    io::NmeaRmc rmc;
    rmc.utc_s = utc_s;
    rmc.valid = true;
    rmc.lat_rad = gga.lat_rad;
    rmc.lon_rad = gga.lon_rad;
    rmc.sog_mps = sog_mps;
    rmc.cog_rad = cog_rad;
    rmc.date = io::add_days(*start.date, day);
    rmc.magnetic_variation_rad = core::kMissing;
    rmc.mode = 'D';
    out.push_back({t[i], io::format_rmc("GN", rmc)});
    io::NmeaVtg vtg;
    vtg.cog_rad = cog_rad;
    vtg.cog_magnetic_rad = core::kMissing;
    vtg.sog_mps = sog_mps;
    vtg.mode = 'D';
    out.push_back({t[i], io::format_vtg("GN", vtg)});
    if (heading != nullptr) {
      for (; next_heading_row <= i; ++next_heading_row) {
        const double h = (*heading)[next_heading_row];
        if (!core::is_missing(h)) last_heading_deg = h;
      }
      if (!core::is_missing(last_heading_deg)) {
        io::NmeaHdt hdt;
        hdt.heading_rad = last_heading_deg * kDegToRad;
        out.push_back({t[i], io::format_hdt("HE", hdt)});
      }
    }
  }
  return out;
}

namespace {

constexpr std::int64_t kMsPerDay = 86'400'000;

// The trial clock: log time [s] → UTC, from the run's start_utc.
struct TrialClock {
  io::UtcDate date;
  double start_time_of_day_s = 0.0;

  explicit TrialClock(const std::string& start_utc) {
    const io::UtcTimestamp start = io::parse_utc_timestamp(start_utc);
    if (!start.date) throw std::invalid_argument("ScenarioRun::start_utc has no date");
    date = *start.date;
    start_time_of_day_s = start.time_of_day_s;
  }
  // Milliseconds since 00:00 UTC of `date` (past 86 400 000 after midnight).
  std::int64_t ms_of(double t_s) const { return std::llround((start_time_of_day_s + t_s) * 1e3); }
  std::int64_t epoch_ms(double t_s) const {
    return io::days_since_epoch(date) * kMsPerDay + ms_of(t_s);
  }
  // "YYYY-MM-DD?HH:MM:SS.mmm" with `separator` between date and time.
  std::string iso(double t_s, char separator) const {
    const std::int64_t ms = ms_of(t_s);
    const std::int64_t day = ms / kMsPerDay;  // ms ≥ 0: t ≥ 0 and start ≥ 00:00
    const std::int64_t in_day = ms - day * kMsPerDay;
    return fmt::format("{}{}{:02}:{:02}:{:02}.{:03}", io::to_iso(io::add_days(date, day)),
                       separator, in_day / 3'600'000, in_day / 60'000 % 60, in_day / 1000 % 60,
                       in_day % 1000);
  }
};

std::string cell(double value) { return core::is_missing(value) ? "" : fmt::format("{}", value); }

// "rpm.port" → "port_rpm", "command.rpm.port" → "order_rpm_port", "lever.surge" → "lever_surge".
std::string device_column(const std::string& channel) {
  std::string name = channel;
  if (name.rfind("command.", 0) == 0) name = "order." + name.substr(8);
  for (const char* kind : {"rpm.", "thrust.", "power.", "rudder."}) {
    const std::string k(kind);
    if (channel.rfind(k, 0) == 0) name = channel.substr(k.size()) + "." + k.substr(0, k.size() - 1);
  }
  for (char& c : name) c = c == '.' ? '_' : c;
  return name;
}

std::string header_cell(const core::Channel& c, const std::string& name) {
  return c.unit.empty() ? name : fmt::format("{} [{}]", name, c.unit);
}

// The rows of the log at `rate_hz` (t a whole multiple of its period).
std::vector<std::size_t> rows_at_rate(const core::Log& log, double rate_hz) {
  std::vector<std::size_t> rows;
  for (std::size_t i = 0; i < log.size(); ++i) {
    const double k = log.time()[i] * rate_hz;
    if (std::abs(k - std::round(k)) < 1e-6) rows.push_back(i);
  }
  return rows;
}

void write_capture(const ScenarioRun& run, const TrialClock& clock, const std::string& antenna,
                   const std::filesystem::path& path) {
  const std::vector<TimedSentence> sentences = gnss_sentences(run, antenna);
  io::AtomicFile file(path);
  for (std::size_t k = 0; k < sentences.size(); ++k) {
    std::string line = clock.iso(sentences[k].t_s, 'T') + "Z " + sentences[k].text;
    // The capture starts and stops in the middle of a line.
    if (k == 0) line = line.substr(line.size() / 2);
    if (k + 1 == sentences.size()) {
      file.stream() << line.substr(0, line.size() / 2);
    } else {
      file.stream() << line << "\r\n";
    }
  }
  file.commit();
}

void write_mru(const ScenarioRun& run, const TrialClock& clock, const std::filesystem::path& path) {
  const core::Log& log = run.log;
  const std::vector<std::pair<std::string, std::string>> columns = {
      {"mru1.roll", "Roll"},   {"mru1.pitch", "Pitch"}, {"mru1.p", "RollRate"},
      {"mru1.q", "PitchRate"}, {"mru1.r", "YawRate"},   {"mru1.ax", "AccX"},
      {"mru1.ay", "AccY"},     {"mru1.az", "AccZ"}};
  io::AtomicFile file(path);
  std::ostream& out = file.stream();
  out << "Time";
  for (const auto& [channel, name] : columns) out << "," << header_cell(log.channel(channel), name);
  out << "\n";
  const std::vector<double>& roll = log.values("mru1.roll");
  for (std::size_t i = 0; i < log.size(); ++i) {
    if (core::is_missing(roll[i])) continue;
    out << clock.iso(log.time()[i], ' ') << "+00:00";
    for (const auto& [channel, name] : columns) out << "," << cell(log.values(channel)[i]);
    out << "\n";
  }
  file.commit();
}

}  // namespace

namespace {

bool has_prefix(const std::string& name, std::initializer_list<const char*> prefixes) {
  for (const char* p : prefixes) {
    if (name.rfind(p, 0) == 0) return true;
  }
  return false;
}

// Feedback at its own rate: each value the latest the device had at or before the row.
void write_feedback(const ScenarioRun& run, const TrialClock& clock, double rate_hz,
                    const std::filesystem::path& path) {
  const core::Log& log = run.log;
  std::vector<const core::Channel*> channels;
  for (const core::Channel& c : log.channels()) {
    if (has_prefix(c.name, {"rpm.", "thrust.", "power.", "rudder."})) channels.push_back(&c);
  }
  io::AtomicFile file(path);
  std::ostream& out = file.stream();
  out << "EpochMs";
  for (const core::Channel* c : channels) out << "," << header_cell(*c, device_column(c->name));
  out << "\n";
  std::vector<double> latest(channels.size(), core::kMissing);
  std::size_t next = 0;
  for (const std::size_t row : rows_at_rate(log, rate_hz)) {
    for (; next <= row; ++next) {
      for (std::size_t k = 0; k < channels.size(); ++k) {
        const double v = channels[k]->values[next];
        if (!core::is_missing(v)) latest[k] = v;
      }
    }
    out << clock.epoch_ms(log.time()[row]);
    for (const double v : latest) out << "," << cell(v);
    out << "\n";
  }
  file.commit();
}

// The half-width of the dither on an order channel, by what it orders.
double wiggle_of(const core::Channel& c, const DeviceFilesSpec& spec) {
  if (c.name.find("rpm") != std::string::npos) return spec.order_wiggle_rpm;
  if (c.name.find("rudder") != std::string::npos) return spec.order_wiggle_deg;
  if (c.unit == "%") return spec.order_wiggle_pct;
  return 0.0;
}

void write_orders(const ScenarioRun& run, const TrialClock& clock, const DeviceFilesSpec& spec,
                  const std::filesystem::path& path) {
  const core::Log& log = run.log;
  std::vector<const core::Channel*> channels;
  for (const core::Channel& c : log.channels()) {
    if (has_prefix(c.name, {"command.", "lever."})) channels.push_back(&c);
  }
  sim::Rng rng(run.truth.seed, "device_files.orders");
  io::AtomicFile file(path);
  std::ostream& out = file.stream();
  out << "sec,nsec";
  for (const core::Channel* c : channels) out << "," << header_cell(*c, device_column(c->name));
  out << "\n";
  for (const std::size_t row : rows_at_rate(log, spec.feedback_rate_hz)) {
    const std::int64_t ms = clock.epoch_ms(log.time()[row]);
    out << ms / 1000 << "," << (ms % 1000) * 1'000'000;
    for (const core::Channel* c : channels) {
      const double w = wiggle_of(*c, spec);
      const double dither = w > 0.0 ? rng.uniform(-w, w) : 0.0;
      out << "," << cell(c->values[row] + dither);
    }
    out << "\n";
  }
  file.commit();
}

}  // namespace

void write_device_files(const ScenarioRun& run, const DeviceFilesSpec& spec,
                        const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  const TrialClock clock(run.start_utc);
  for (const std::string& antenna : gnss_antennas(run.log)) {
    write_capture(run, clock, antenna, dir / (antenna + ".nmea"));
  }
  if (run.log.has("mru1.roll")) write_mru(run, clock, dir / "mru.csv");
  write_feedback(run, clock, spec.feedback_rate_hz, dir / "thrusters.csv");
  write_orders(run, clock, spec, dir / "orders.csv");
}

}  // namespace dynpos::scenario
