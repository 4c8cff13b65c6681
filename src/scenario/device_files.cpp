#include "dynpos/scenario/device_files.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <utility>

#include "dynpos/io/atomic_file.hpp"
#include "dynpos/io/nmea.hpp"
#include "dynpos/io/nmea_writer.hpp"
#include "dynpos/io/temporary_files.hpp"
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
GnssSentenceStream::GnssSentenceStream(const core::Log& layout, const std::string& antenna,
                                       const RunFileContext& context)
    : geoid_separation_m_(context.geoid_separation_m) {
  const io::UtcTimestamp start = io::parse_utc_timestamp(context.start_utc);
  if (!start.date) throw std::invalid_argument("the run's start_utc has no date");
  start_date_ = *start.date;
  start_time_of_day_s_ = start.time_of_day_s;
  const auto index = [&](const std::string& name) {
    const auto& channels = layout.channels();
    for (std::size_t k = 0; k < channels.size(); ++k) {
      if (channels[k].name == name) return k;
    }
    throw std::out_of_range("no channel '" + name + "' for the NMEA sentences");
  };
  lat_ = index(antenna + ".lat");
  lon_ = index(antenna + ".lon");
  height_ = index(antenna + ".height");
  north_ = index(antenna + ".north");
  east_ = index(antenna + ".east");
  if (layout.has("heading")) heading_ = index("heading");
}

void GnssSentenceStream::add(const core::Log& block, std::vector<TimedSentence>& out) {
  const auto& c = block.channels();
  for (std::size_t i = 0; i < block.size(); ++i) {
    if (heading_) {
      const double h = c[*heading_].values[i];
      if (!core::is_missing(h)) last_heading_deg_ = h;
    }
    const double lat = c[lat_].values[i], lon = c[lon_].values[i];
    if (core::is_missing(lat) || core::is_missing(lon)) continue;
    const Fix fix{
        block.time()[i],  lat, lon, c[height_].values[i], c[north_].values[i], c[east_].values[i],
        last_heading_deg_};
    if (pending_) send(*pending_, before_ ? *before_ : *pending_, fix, true, out);
    before_ = pending_;
    pending_ = fix;
  }
}

void GnssSentenceStream::finish(std::vector<TimedSentence>& out) {
  if (pending_)
    send(*pending_, before_ ? *before_ : *pending_, *pending_, before_.has_value(), out);
  before_.reset();
  pending_.reset();
}

void GnssSentenceStream::send(const Fix& fix, const Fix& before, const Fix& after, bool has_track,
                              std::vector<TimedSentence>& out) const {
  constexpr double kDegToRad = std::numbers::pi / 180.0;
  const double utc_s = start_time_of_day_s_ + fix.t_s;
  const long day = static_cast<long>(std::floor((utc_s + 0.0005) / 86400.0));
  // Track velocity [m/s] from the neighbouring fixes.
  double sog_mps = core::kMissing, cog_rad = core::kMissing;
  if (has_track) {
    const double dn = after.north_m - before.north_m, de = after.east_m - before.east_m;
    sog_mps = std::hypot(dn, de) / (after.t_s - before.t_s);
    cog_rad = std::atan2(de, dn);
  }
  io::NmeaGga gga;
  gga.utc_s = utc_s;
  gga.lat_rad = fix.lat_deg * kDegToRad;
  gga.lon_rad = fix.lon_deg * kDegToRad;
  gga.quality = 4;
  gga.satellites = core::kMissing;
  gga.hdop = core::kMissing;
  gga.altitude_m = fix.height_m - geoid_separation_m_;
  gga.geoid_separation_m = geoid_separation_m_;
  gga.age_s = core::kMissing;
  out.push_back({fix.t_s, io::format_gga("GN", gga)});
  io::NmeaRmc rmc;
  rmc.utc_s = utc_s;
  rmc.valid = true;
  rmc.lat_rad = gga.lat_rad;
  rmc.lon_rad = gga.lon_rad;
  rmc.sog_mps = sog_mps;
  rmc.cog_rad = cog_rad;
  rmc.date = io::add_days(start_date_, day);
  rmc.magnetic_variation_rad = core::kMissing;
  rmc.mode = 'D';
  out.push_back({fix.t_s, io::format_rmc("GN", rmc)});
  io::NmeaVtg vtg;
  vtg.cog_rad = cog_rad;
  vtg.cog_magnetic_rad = core::kMissing;
  vtg.sog_mps = sog_mps;
  vtg.mode = 'D';
  out.push_back({fix.t_s, io::format_vtg("GN", vtg)});
  if (heading_ && !core::is_missing(fix.heading_deg)) {
    io::NmeaHdt hdt;
    hdt.heading_rad = fix.heading_deg * kDegToRad;
    out.push_back({fix.t_s, io::format_hdt("HE", hdt)});
  }
}

namespace {

constexpr std::int64_t kMsPerDay = 86'400'000;

// The trial clock: log time [s] → UTC, from the run's start_utc.
struct UtcClock {
  io::UtcDate date;
  double start_time_of_day_s = 0.0;

  explicit UtcClock(const std::string& start_utc) {
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
  for (const char* kind : {"rpm.", "thrust.", "power.", "rudder.", "azimuth."}) {
    const std::string k(kind);
    if (channel.rfind(k, 0) == 0) name = channel.substr(k.size()) + "." + k.substr(0, k.size() - 1);
  }
  for (char& c : name) c = c == '.' ? '_' : c;
  return name;
}

std::string header_cell(const core::Channel& c, const std::string& name) {
  return c.unit.empty() ? name : fmt::format("{} [{}]", name, c.unit);
}

// True when t is a whole multiple of the period of `rate_hz`.
bool at_rate(double t_s, double rate_hz) {
  const double k = t_s * rate_hz;
  return std::abs(k - std::round(k)) < 1e-6;
}

bool has_prefix(const std::string& name, std::initializer_list<const char*> prefixes) {
  for (const char* p : prefixes) {
    if (name.rfind(p, 0) == 0) return true;
  }
  return false;
}

// The indices of the channels whose names start with one of `prefixes`.
std::vector<std::size_t> channels_named(const core::Log& layout,
                                        std::initializer_list<const char*> prefixes) {
  std::vector<std::size_t> out;
  for (std::size_t k = 0; k < layout.channels().size(); ++k) {
    if (has_prefix(layout.channels()[k].name, prefixes)) out.push_back(k);
  }
  return out;
}

// devices/gnssK.nmea: the sentences behind a logger stamp; the capture starts and stops in the
// middle of a line, so each line waits for the next (the last one is cut at commit()).
class CaptureWriter {
 public:
  CaptureWriter(const core::Log& layout, const std::string& antenna, const RunFileContext& context,
                const std::filesystem::path& path)
      : sentences_(layout, antenna, context), file_(path) {}

  void add(const UtcClock& clock, const core::Log& block) {
    batch_.clear();
    sentences_.add(block, batch_);
    write(clock);
  }
  void commit(const UtcClock& clock) {
    batch_.clear();
    sentences_.finish(batch_);
    write(clock);
    if (line_) file_.stream() << line_->substr(0, line_->size() / 2);
    file_.commit();
  }

 private:
  void write(const UtcClock& clock) {
    for (const TimedSentence& s : batch_) {
      std::string line = clock.iso(s.t_s, 'T') + "Z " + s.text;
      if (!line_) {
        line = line.substr(line.size() / 2);  // the first line, from its middle
      } else {
        file_.stream() << *line_ << "\r\n";
      }
      line_ = std::move(line);
    }
  }

  GnssSentenceStream sentences_;
  io::AtomicFile file_;
  std::vector<TimedSentence> batch_;
  std::optional<std::string> line_;  // the latest line, not yet written
};

// devices/mru.csv: MRU 1 at its own rate, the rows where it has a sample.
class MruWriter {
 public:
  MruWriter(const core::Log& layout, const std::filesystem::path& path) : file_(path) {
    const std::pair<const char*, const char*> columns[] = {
        {"mru1.roll", "Roll"},   {"mru1.pitch", "Pitch"}, {"mru1.p", "RollRate"},
        {"mru1.q", "PitchRate"}, {"mru1.r", "YawRate"},   {"mru1.ax", "AccX"},
        {"mru1.ay", "AccY"},     {"mru1.az", "AccZ"}};
    std::ostream& out = file_.stream();
    out << "Time";
    for (const auto& [channel, name] : columns) {
      out << "," << header_cell(layout.channel(channel), name);
      for (std::size_t k = 0; k < layout.channels().size(); ++k) {
        if (layout.channels()[k].name == channel) columns_.push_back(k);
      }
    }
    out << "\n";
  }
  void add(const UtcClock& clock, const core::Log& block) {
    std::ostream& out = file_.stream();
    const auto& c = block.channels();
    for (std::size_t i = 0; i < block.size(); ++i) {
      if (core::is_missing(c[columns_.front()].values[i])) continue;  // no roll: no sample
      out << clock.iso(block.time()[i], ' ') << "+00:00";
      for (const std::size_t k : columns_) out << "," << cell(c[k].values[i]);
      out << "\n";
    }
  }
  void commit() { file_.commit(); }

 private:
  io::AtomicFile file_;
  std::vector<std::size_t> columns_;
};

// A device CSV at the feedback rate: its file, its channels and its header (the time columns,
// then a column per channel).
struct RateFile {
  io::AtomicFile file;
  double rate_hz;
  std::vector<std::size_t> channels;

  RateFile(const core::Log& layout, double rate, std::initializer_list<const char*> prefixes,
           const char* time_columns, const std::filesystem::path& path)
      : file(path), rate_hz(rate), channels(channels_named(layout, prefixes)) {
    std::ostream& out = file.stream();
    out << time_columns;
    for (const std::size_t k : channels) {
      const core::Channel& c = layout.channels()[k];
      out << "," << header_cell(c, device_column(c.name));
    }
    out << "\n";
  }
};

// devices/thrusters.csv: feedback at its own rate, each value the latest the device had at or
// before the row.
class FeedbackWriter {
 public:
  FeedbackWriter(const core::Log& layout, double rate_hz, const std::filesystem::path& path)
      : out_(layout, rate_hz, {"rpm.", "thrust.", "power.", "rudder.", "azimuth."}, "EpochMs",
             path),
        latest_(out_.channels.size(), core::kMissing) {}
  void add(const UtcClock& clock, const core::Log& block) {
    std::ostream& out = out_.file.stream();
    for (std::size_t i = 0; i < block.size(); ++i) {
      for (std::size_t k = 0; k < latest_.size(); ++k) {
        const double v = block.channels()[out_.channels[k]].values[i];
        if (!core::is_missing(v)) latest_[k] = v;
      }
      if (!at_rate(block.time()[i], out_.rate_hz)) continue;
      out << clock.epoch_ms(block.time()[i]);
      for (const double v : latest_) out << "," << cell(v);
      out << "\n";
    }
  }
  void commit() { out_.file.commit(); }

 private:
  RateFile out_;
  std::vector<double> latest_;
};

// The half-width of the dither on an order channel, by what it orders (by its kind, not by a
// unit's name, which may be anything).
double wiggle_of(const core::Channel& c, const DeviceFilesSpec& spec) {
  if (has_prefix(c.name, {"command.rpm."})) return spec.order_wiggle_rpm;
  if (has_prefix(c.name, {"command.rudder.", "command.azimuth."})) return spec.order_wiggle_deg;
  if (c.unit == "%") return spec.order_wiggle_pct;
  return 0.0;
}

// devices/orders.csv: the orders at the feedback rate, each with its dither.
class OrderWriter {
 public:
  OrderWriter(const core::Log& layout, const RunFileContext& context,
              const std::filesystem::path& path)
      : out_(layout, context.device_files->feedback_rate_hz, {"command.", "lever."}, "sec,nsec",
             path),
        rng_(context.seed, "device_files.orders") {
    for (const std::size_t k : out_.channels) {
      wiggle_.push_back(wiggle_of(layout.channels()[k], *context.device_files));
    }
  }
  void add(const UtcClock& clock, const core::Log& block) {
    std::ostream& out = out_.file.stream();
    for (std::size_t i = 0; i < block.size(); ++i) {
      if (!at_rate(block.time()[i], out_.rate_hz)) continue;
      const std::int64_t ms = clock.epoch_ms(block.time()[i]);
      out << ms / 1000 << "," << (ms % 1000) * 1'000'000;
      for (std::size_t k = 0; k < wiggle_.size(); ++k) {
        const double w = wiggle_[k];
        const double dither = w > 0.0 ? rng_.uniform(-w, w) : 0.0;
        out << "," << cell(block.channels()[out_.channels[k]].values[i] + dither);
      }
      out << "\n";
    }
  }
  void commit() { out_.file.commit(); }

 private:
  RateFile out_;
  std::vector<double> wiggle_;
  sim::Rng rng_;
};

}  // namespace

struct DeviceFileWriter::Files {
  UtcClock clock;
  std::vector<std::unique_ptr<CaptureWriter>> captures;
  std::optional<MruWriter> mru;
  std::optional<FeedbackWriter> feedback;
  std::optional<OrderWriter> orders;
};

DeviceFileWriter::DeviceFileWriter(const core::Log& layout, const RunFileContext& context,
                                   const std::filesystem::path& dir) {
  if (!context.device_files) throw std::invalid_argument("DeviceFileWriter: no device files");
  {
    const io::temporary_files::Hold hold;  // in a run's stage: not after a signal's removal
    std::filesystem::create_directories(dir);
  }
  files_.reset(new Files{UtcClock(context.start_utc), {}, {}, {}, {}});  // cannot move: in place
  for (const std::string& antenna : gnss_antennas(layout)) {
    files_->captures.push_back(
        std::make_unique<CaptureWriter>(layout, antenna, context, dir / (antenna + ".nmea")));
  }
  if (layout.has("mru1.roll")) files_->mru.emplace(layout, dir / "mru.csv");
  files_->feedback.emplace(layout, context.device_files->feedback_rate_hz, dir / "thrusters.csv");
  files_->orders.emplace(layout, context, dir / "orders.csv");
}

DeviceFileWriter::~DeviceFileWriter() = default;

void DeviceFileWriter::add(const core::Log& block) {
  for (const auto& capture : files_->captures) capture->add(files_->clock, block);
  if (files_->mru) files_->mru->add(files_->clock, block);
  files_->feedback->add(files_->clock, block);
  files_->orders->add(files_->clock, block);
}

void DeviceFileWriter::commit() {
  for (const auto& capture : files_->captures) capture->commit(files_->clock);
  if (files_->mru) files_->mru->commit();
  files_->feedback->commit();
  files_->orders->commit();
}

}  // namespace dynpos::scenario
