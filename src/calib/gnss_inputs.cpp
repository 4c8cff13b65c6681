// Log adapters of the GNSS lever-arm estimators: the motion of a mixed-rate log and the
// antennas' fixes in one local NED frame (gnss_lever_arm.hpp).

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "dynpos/calib/gnss_lever_arm.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/core/local_ned_frame.hpp"
#include "resample_onto.hpp"

namespace dynpos::calib {
namespace {

core::InputError missing(const std::string& role, const std::string& file = {}) {
  return core::InputError(
      {file, {}, {}, role},
      "the GNSS lever-arm estimators need the role '" + role + "', not in the log",
      "map it with --col " + role + "=COLUMN (and --unit " + role + "=UNIT if not SI)");
}

using detail::resample_onto;

}  // namespace

MotionFromLog motion_from_mixed_log(const core::Log& log) {
  const std::vector<std::string> roles = {"roll", "pitch", "heading", "p", "q", "r", "u", "v"};
  for (const std::string& r : roles)
    if (!log.has(r)) throw missing(r);
  MotionFromLog out;
  const bool heave = log.has("w");
  if (!heave) out.notes.emplace_back("w (heave speed) not logged: taken as 0");
  const std::vector<double>& t = log.time();
  std::vector<double> grid;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (std::isfinite(log.values("roll")[i])) grid.push_back(t[i]);
  std::vector<std::vector<double>> cols;
  for (const std::string& r : roles)
    cols.push_back(resample_onto(t, log.values(r), grid, r == "heading"));
  if (heave) cols.push_back(resample_onto(t, log.values("w"), grid, false));
  MotionSeries& m = out.motion;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    bool ok = true;
    for (const auto& c : cols) ok = ok && std::isfinite(c[i]);
    if (!ok) {
      ++out.rows_skipped;
      continue;
    }
    m.t_s.push_back(grid[i]);
    m.theta_rad.emplace_back(cols[0][i], cols[1][i], cols[2][i]);
    m.omega_b_rps.emplace_back(cols[3][i], cols[4][i], cols[5][i]);
    m.v_b_mps.emplace_back(cols[6][i], cols[7][i], heave ? cols[8][i] : 0.0);
  }
  if (m.size() < 3) {
    throw core::InputError({{}, {}, {}, "time"},
                           "fewer than three rows carry the motion (roll, pitch, heading, p, q, "
                           "r, u, v) within the time all of them are logged (" +
                               std::to_string(m.size()) + ")",
                           "check that the motion channels are logged over the same time span");
  }
  return out;
}

std::vector<std::string> gnss_prefixes(const core::Log& log) {
  std::vector<std::pair<int, std::string>> found;
  for (const std::string& name : log.channel_names()) {
    if (name.rfind("gnss", 0) != 0) continue;
    const auto dot = name.find('.');
    if (dot == std::string::npos) continue;
    const std::string field = name.substr(dot + 1);
    if (field != "north" && field != "lat") continue;
    const std::string num = name.substr(4, dot - 4);
    if (num.empty() || !std::all_of(num.begin(), num.end(), ::isdigit)) continue;
    found.emplace_back(std::stoi(num), name.substr(0, dot));
  }
  std::sort(found.begin(), found.end());
  std::vector<std::string> out;
  for (const auto& f : found)
    if (out.empty() || out.back() != f.second) out.push_back(f.second);
  return out;
}

std::vector<GnssSeries> gnss_from_logs(const std::vector<GnssSource>& sources) {
  auto has_all = [](const GnssSource& s, const char* a, const char* b, const char* c) {
    return s.log->has(s.prefix + a) && s.log->has(s.prefix + b) && s.log->has(s.prefix + c);
  };
  bool ned = true;
  bool geo = true;
  for (const GnssSource& s : sources) {
    ned = ned && has_all(s, ".north", ".east", ".down");
    geo = geo && has_all(s, ".lat", ".lon", ".height");
  }
  if (!ned && !geo) {
    for (const GnssSource& s : sources) {
      if (!has_all(s, ".north", ".east", ".down") && !has_all(s, ".lat", ".lon", ".height"))
        throw core::InputError(
            {s.file, {}, {}, s.prefix + ".lat"},
            "antenna '" + s.prefix + "' has neither " + s.prefix + ".lat/.lon/.height nor " +
                s.prefix + ".north/.east/.down",
            "map the three position columns with --col " + s.prefix + ".lat=COLUMN etc.");
    }
    throw core::InputError({{}, {}, {}, sources.front().prefix + ".lat"},
                           "some antennas are given in NED and others in latitude/longitude",
                           "give every antenna the same kind of position (both frames must share "
                           "one origin)");
  }
  std::optional<core::LocalNedFrame> frame;
  const double deg = 180.0 / std::numbers::pi;
  std::vector<GnssSeries> out;
  for (const GnssSource& s : sources) {
    const char* f[3] = {ned ? ".north" : ".lat", ned ? ".east" : ".lon", ned ? ".down" : ".height"};
    const auto& a = s.log->values(s.prefix + f[0]);
    const auto& b = s.log->values(s.prefix + f[1]);
    const auto& c = s.log->values(s.prefix + f[2]);
    GnssSeries g;
    g.name = s.prefix;
    const auto& t = s.log->time();
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (std::isnan(a[i]) || std::isnan(b[i]) || std::isnan(c[i])) continue;
      if (!std::isfinite(a[i]) || !std::isfinite(b[i]) || !std::isfinite(c[i]))
        throw core::InputError({s.file, {}, {}, s.prefix + f[0]},
                               "antenna '" + s.prefix + "' has an infinite position at t = " +
                                   std::to_string(t[i]) + " s",
                               "remove or blank the bad row");
      Eigen::Vector3d p;
      if (ned) {
        p = Eigen::Vector3d(a[i], b[i], c[i]);
      } else {
        const core::GeodeticPoint fix{a[i] * deg, b[i] * deg, c[i]};
        if (!frame) frame.emplace(fix);
        p = frame->to_ned(fix);
      }
      g.t_s.push_back(t[i]);
      g.p_n_m.push_back(p);
    }
    if (g.t_s.size() < 3)
      throw core::InputError({s.file, {}, {}, s.prefix + f[0]},
                             "antenna '" + s.prefix + "' has " + std::to_string(g.t_s.size()) +
                                 " fixes: need at least 3",
                             "check the GNSS columns (blank cells are missing fixes)");
    out.push_back(std::move(g));
  }
  return out;
}

}  // namespace dynpos::calib
