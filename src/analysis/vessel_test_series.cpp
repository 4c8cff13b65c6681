// Reading a logged test for the vessel fit (vessel_test_series.hpp).

#include "vessel_test_series.hpp"

#include <algorithm>
#include <cmath>

#include "dynpos/core/angle.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/core/time_spacing.hpp"

namespace dynpos::analysis::vessel_fit {

bool wanted_role(const std::string& role) {
  static const std::vector<std::string> exact{"time",       "heading",  "u",     "v",   "r",
                                              "wind_speed", "wind_dir", "north", "east"};
  if (std::find(exact.begin(), exact.end(), role) != exact.end()) return true;
  for (const char* prefix :
       {"thrust.", "rudder.", "azimuth.", "rpm.", "command.rpm.", "command.azimuth."}) {
    if (role.rfind(prefix, 0) == 0) return true;
  }
  const bool mru =
      role.rfind("mru", 0) == 0 && role.size() > 5 && role.compare(role.size() - 2, 2, ".r") == 0;
  return mru || role == "gnss1.north" || role == "gnss1.east";
}

namespace {

// The valid samples of `values` interpolated at `grid` (linear, angles along the shorter arc),
// held before the first and after the last; empty when none is valid.
std::vector<double> at_grid(const std::vector<double>& t, const std::vector<double>& values,
                            const std::vector<double>& grid, bool angle) {
  std::vector<std::size_t> valid;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!core::is_missing(values[i])) valid.push_back(i);
  }
  if (valid.empty()) return {};
  std::vector<double> out(grid.size());
  std::size_t j = 0;
  for (std::size_t g = 0; g < grid.size(); ++g) {
    while (j + 1 < valid.size() && t[valid[j + 1]] <= grid[g]) ++j;
    const std::size_t a = valid[j];
    if (grid[g] <= t[a] || j + 1 == valid.size()) {
      out[g] = values[a];
      continue;
    }
    const std::size_t b = valid[j + 1];
    const double w = (grid[g] - t[a]) / (t[b] - t[a]);
    const double d = angle ? core::wrap_pi(values[b] - values[a]) : values[b] - values[a];
    out[g] = values[a] + w * d;
  }
  return out;
}

// The yaw rate's role: r, else the first MRU's.
std::optional<std::string> yaw_rate_role(const core::Log& log) {
  if (log.has("r")) return "r";
  for (const std::string& name : log.channel_names()) {
    if (name.rfind("mru", 0) == 0 && name.size() > 5 &&
        name.compare(name.size() - 2, 2, ".r") == 0) {
      return name;
    }
  }
  return std::nullopt;
}

// A needed input at the grid, or the log's error naming the role.
std::vector<double> needed(const LogSource& source, const core::Log& log, const std::string& role,
                           const std::vector<double>& grid, bool angle, const std::string& why) {
  std::vector<double> out;
  if (log.has(role)) out = at_grid(log.time(), log.values(role), grid, angle);
  if (out.empty()) {
    throw source.error(role, "the log has no " + role + " (" + why + ")",
                       "map it with --col " + role + "=COLUMN");
  }
  return out;
}

void add_measured(FitTest& test, int c, const std::vector<double>& t,
                  const std::vector<double>& values, double t0, double step_s, double sample_s) {
  const std::size_t n = test.drive.size();
  double last = -1e300;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (core::is_missing(values[i]) || t[i] < last + sample_s - 1e-9) continue;
    const auto g = static_cast<std::size_t>(std::llround((t[i] - t0) / step_s));
    if (g >= n || std::abs(test.drive.time_s[g] - t[i]) > 0.5 * step_s) continue;
    test.index[static_cast<std::size_t>(c)].push_back(g);
    test.measured[static_cast<std::size_t>(c)].push_back(values[i]);
    last = t[i];
  }
}

// The mean of each channel's samples within 5 s of sample `from` (0 when none).
Eigen::Vector3d start_guess(const FitTest& t, std::size_t from) {
  Eigen::Vector3d out = Eigen::Vector3d::Zero();
  const double t0 = t.drive.time_s[from];
  for (std::size_t c = 0; c < 3; ++c) {
    double sum = 0.0;
    int count = 0;
    for (std::size_t m = 0; m < t.index[c].size(); ++m) {
      const double tm = t.drive.time_s[t.index[c][m]];
      if (tm >= t0 && tm <= t0 + 5.0) {
        sum += t.measured[c][m];
        ++count;
      }
    }
    out[static_cast<int>(c)] = count > 0 ? sum / count : 0.0;
  }
  return out;
}

}  // namespace

std::vector<FitTest> cut(const FitTest& whole, double stretch_s) {
  const std::size_t n = whole.drive.size();
  const double span = whole.drive.time_s.back() - whole.drive.time_s.front();
  const auto pieces = static_cast<std::size_t>(std::max(1.0, std::round(span / stretch_s)));
  std::vector<FitTest> out;
  for (std::size_t p = 0; p < pieces; ++p) {
    const std::size_t a = p * (n - 1) / pieces, b = (p + 1) * (n - 1) / pieces;
    FitTest t;
    t.name = whole.name;
    t.first = a;
    const scenario::DriveSeries& d = whole.drive;
    auto part = [&](const std::vector<double>& v) {
      return v.empty() ? v
                       : std::vector<double>(v.begin() + static_cast<std::ptrdiff_t>(a),
                                             v.begin() + static_cast<std::ptrdiff_t>(b + 1));
    };
    t.drive.time_s = part(d.time_s);
    t.drive.heading_rad = part(d.heading_rad);
    for (const auto& v : d.thrust_N) t.drive.thrust_N.push_back(part(v));
    for (const auto& v : d.angle_rad) t.drive.angle_rad.push_back(part(v));
    t.drive.wind_speed_mps = part(d.wind_speed_mps);
    t.drive.wind_from_rad = part(d.wind_from_rad);
    for (std::size_t c = 0; c < 3; ++c) {
      for (std::size_t m = 0; m < whole.index[c].size(); ++m) {
        const std::size_t i = whole.index[c][m];
        // A boundary sample is the later stretch's (the earlier one ends on it).
        if (i >= a && (i < b || (p + 1 == pieces && i == b))) {
          t.index[c].push_back(i - a);
          t.measured[c].push_back(whole.measured[c][m]);
        }
      }
    }
    t.nu0_guess = start_guess(whole, a);
    if (t.residual_count() > 0) out.push_back(std::move(t));
  }
  return out;
}

LoggedTest read_test(const LogSource& source, const scenario::ThrustFeedback& feedback,
                     double step_s, double sample_s, double stretch_s) {
  LoadedLog loaded = source.load(wanted_role);
  const core::Log& log = loaded.log;
  LoggedTest out;
  out.input = std::move(loaded.input);
  FitTest& test = out.whole;
  test.name = source.log.string();
  if (log.size() < 2) throw source.error("time", "the log has fewer than two rows");
  const double t0 = log.time().front(), t1 = log.time().back();
  std::vector<double>& grid = test.drive.time_s;
  const auto n = static_cast<std::size_t>(std::floor((t1 - t0) / step_s + 1e-9)) + 1;
  for (std::size_t g = 0; g < n; ++g) grid.push_back(t0 + static_cast<double>(g) * step_s);

  test.drive.heading_rad = needed(source, log, "heading", grid, true, "it turns the current");
  for (const scenario::FeedbackChannel& ch : feedback.channels()) {
    test.drive.thrust_N.push_back(
        needed(source, log, ch.thrust_role, grid, false, "the force that drives the hull"));
    test.drive.angle_rad.push_back(
        ch.angle_role.empty()
            ? std::vector<double>(n, 0.0)
            : needed(source, log, ch.angle_role, grid, true, "the direction of the force"));
  }
  if (log.has("wind_speed") && log.has("wind_dir")) {
    test.drive.wind_speed_mps = at_grid(log.time(), log.values("wind_speed"), grid, false);
    test.drive.wind_from_rad = at_grid(log.time(), log.values("wind_dir"), grid, true);
    if (test.drive.wind_speed_mps.empty() || test.drive.wind_from_rad.empty()) {
      test.drive.wind_speed_mps.clear();
      test.drive.wind_from_rad.clear();
    }
  }
  const std::optional<std::string> r = yaw_rate_role(log);
  const std::array<std::optional<std::string>, 3> roles{
      log.has("u") ? std::optional<std::string>("u") : std::nullopt,
      log.has("v") ? std::optional<std::string>("v") : std::nullopt, r};
  for (int c = 0; c < 3; ++c) {
    if (roles[static_cast<std::size_t>(c)]) {
      add_measured(test, c, log.time(), log.values(*roles[static_cast<std::size_t>(c)]), t0, step_s,
                   sample_s);
    }
  }
  if (test.residual_count() == 0) {
    throw source.error("u/v/r", "the log has no surge speed u, sway speed v or yaw rate r",
                       "map the speed log and the rate gyro with --col u=… --col v=… --col r=…");
  }
  test.nu0_guess = start_guess(test, 0);
  out.stretches = cut(test, stretch_s);
  std::vector<std::string> units;
  for (const scenario::FeedbackChannel& ch : feedback.channels()) units.push_back(ch.unit);
  out.units = vessel_units::log_units(test.name, log, units);
  const std::string north = log.has("north") ? "north" : "gnss1.north";
  const std::string east = log.has("east") ? "east" : "gnss1.east";
  if (log.has(north) && log.has(east)) {
    out.north_m = at_grid(log.time(), log.values(north), grid, false);
    out.east_m = at_grid(log.time(), log.values(east), grid, false);
    if (out.north_m.empty() || out.east_m.empty()) {
      out.north_m.clear();
      out.east_m.clear();
    }
  }
  return out;
}

}  // namespace dynpos::analysis::vessel_fit
