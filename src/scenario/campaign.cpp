#include "dynpos/scenario/campaign.hpp"

#include <fmt/core.h>

#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "dynpos/io/atomic_file.hpp"
#include "dynpos/io/csv_writer.hpp"
#include "dynpos/io/json_writer.hpp"
#include "dynpos/io/markup.hpp"
#include "dynpos/io/nmea.hpp"
#include "dynpos/io/nmea_writer.hpp"
#include "dynpos/scenario/runner.hpp"
#include "dynpos/sim/random.hpp"

namespace dynpos::scenario {
namespace {

RunSummary summarise(const ScenarioSpec& spec, const ScenarioRun& run, std::uint64_t seed) {
  RunSummary s;
  s.name = spec.name;
  s.description = spec.description;
  s.duration_s = spec.duration_s;
  s.rows = run.log.size();
  s.seed = seed;
  const core::Log& truth = run.truth_log;  // the summary describes what truly happened
  const auto& t = truth.time();
  const auto& u = truth.values("u");
  const auto& v = truth.values("v");
  const auto& r = truth.values("r");
  const auto& n = truth.values("north");
  const auto& e = truth.values("east");
  const auto& pp = truth.values("power.port");
  const auto& ps = truth.values("power.stb");
  const auto& pt = truth.values("power.tunnel");
  double energy_J = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    s.max_speed_mps = std::max(s.max_speed_mps, std::hypot(u[i], v[i]));
    s.max_yaw_rate_dps = std::max(s.max_yaw_rate_dps, std::abs(r[i]) * 180.0 / M_PI);
    if (i > 0) {
      const double dt = t[i] - t[i - 1];
      s.distance_m += std::hypot(n[i] - n[i - 1], e[i] - e[i - 1]);
      // Trapezoidal ∫P dt over the log samples.
      energy_J += 0.5 * dt * (pp[i] + ps[i] + pt[i] + pp[i - 1] + ps[i - 1] + pt[i - 1]);
    }
  }
  s.energy_kJ = energy_J / 1e3;
  return s;
}

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

// Writes DIR/<antenna>.nmea: per 1 Hz fix of the antenna GNGGA, GNRMC, GNVTG and HEHDT.
// Position and height are the logged fix (GGA altitude = ellipsoidal height − geoid separation,
// with the separation in its own field); fix quality 4 (RTK fixed, as the simulated receivers'
// centimetre noise is); satellites and HDOP are not simulated, so their fields are empty.
// SOG and COG (RMC, VTG) come from the antenna's own track: the central difference of its local
// north/east over the neighbouring fixes (one-sided at the ends). HDT is the gyro compass
// ("heading"), its last sample at or before the fix time. UTC = start_utc + t.
void write_gnss_nmea(const ScenarioRun& run, const std::string& antenna,
                     const std::filesystem::path& path) {
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
  io::AtomicFile file(path);
  std::ostream& out = file.stream();
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
    out << io::format_gga("GN", gga) << "\r\n";
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
    out << io::format_rmc("GN", rmc) << "\r\n";
    io::NmeaVtg vtg;
    vtg.cog_rad = cog_rad;
    vtg.cog_magnetic_rad = core::kMissing;
    vtg.sog_mps = sog_mps;
    vtg.mode = 'D';
    out << io::format_vtg("GN", vtg) << "\r\n";
    if (heading != nullptr) {
      for (; next_heading_row <= i; ++next_heading_row) {
        const double h = (*heading)[next_heading_row];
        if (!core::is_missing(h)) last_heading_deg = h;
      }
      if (!core::is_missing(last_heading_deg)) {
        io::NmeaHdt hdt;
        hdt.heading_rad = last_heading_deg * kDegToRad;
        out << io::format_hdt("HE", hdt) << "\r\n";
      }
    }
  }
  file.commit();
}

}  // namespace

std::uint64_t campaign_seed(std::uint64_t master_seed, const std::string& scenario_name) {
  return sim::stream_seed(master_seed, scenario_name);
}

void write_scenario_run(const ScenarioRun& run, const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  io::write_csv(dir / "log.csv", run.log);
  io::write_csv(dir / "truth.csv", run.truth_log);
  write_trial_truth(run.truth, dir / "truth.json");
  for (const std::string& antenna : gnss_antennas(run.log)) {
    write_gnss_nmea(run, antenna, dir / (antenna + ".nmea"));
  }
}

std::vector<ScenarioSpec> load_campaign(const std::filesystem::path& scenario_dir) {
  std::vector<ScenarioSpec> specs;
  for (const std::string& name : list_scenarios(scenario_dir)) {
    specs.push_back(load_scenario(scenario_dir / (name + ".toml")));
  }
  if (specs.empty()) {
    throw core::InputError({scenario_dir.string(), {}, {}, {}}, "no scenario files found");
  }
  return specs;
}

std::vector<RunSummary> run_campaign(const std::vector<ScenarioSpec>& scenarios,
                                     const VesselConfig& vessel, std::uint64_t master_seed,
                                     const std::filesystem::path& out_dir) {
  std::vector<RunSummary> summaries;
  for (const ScenarioSpec& spec : scenarios) {
    const std::uint64_t seed = campaign_seed(master_seed, spec.name);
    const auto start = std::chrono::steady_clock::now();
    const ScenarioRun run = run_scenario(spec, vessel, seed);
    const std::filesystem::path dir = out_dir / spec.name;
    write_scenario_run(run, dir);
    RunSummary s = summarise(spec, run, seed);
    s.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    summaries.push_back(s);
  }
  return summaries;
}

}  // namespace dynpos::scenario
