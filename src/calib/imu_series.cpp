#include "dynpos/calib/imu_series.hpp"

#include <algorithm>
#include <cmath>

#include "dynpos/core/error.hpp"
#include "dynpos/core/time_spacing.hpp"
#include "resample_onto.hpp"

namespace dynpos::calib {
namespace {

const char* const kImuFields[8] = {"roll", "pitch", "p", "q", "r", "ax", "ay", "az"};

core::InputError missing(const std::string& role) {
  return core::InputError(
      {{}, {}, {}, role},
      "the logger-only lever-arm estimator needs the role '" + role + "', not in the log",
      "map it with --col " + role + "=COLUMN (and --unit " + role + "=UNIT if not SI)");
}

// Median of |x|, the robust scale of a zero-mean series (σ = 1.4826·MAD for Gaussian noise).
double median_abs(std::vector<double> x) {
  for (double& v : x) v = std::abs(v);
  const auto mid = x.begin() + static_cast<long>(x.size() / 2);
  std::nth_element(x.begin(), mid, x.end());
  return *mid;
}

}  // namespace

ImuSeries imu_from_log(const core::Log& log, const std::string& name, MruAccel accel) {
  for (const char* f : kImuFields)
    if (!log.has(name + "." + f)) throw missing(name + "." + f);
  if (!log.has("heading")) throw missing("heading");
  const std::vector<double>& t = log.time();
  std::vector<const std::vector<double>*> cols;
  for (const char* f : kImuFields) cols.push_back(&log.values(name + "." + f));
  std::vector<double> grid;
  std::vector<std::size_t> rows;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (std::all_of(cols.begin(), cols.end(),
                    [i](const auto* c) { return std::isfinite((*c)[i]); })) {
      grid.push_back(t[i]);
      rows.push_back(i);
    }
  }
  const std::vector<double>& heading = log.values("heading");
  const std::vector<double> psi = detail::resample_onto(t, heading, grid, true);
  ImuSeries imu;
  imu.name = name;
  std::vector<double> heading_t;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (std::isfinite(heading[i])) heading_t.push_back(t[i]);
  if (heading_t.size() >= 2) imu.heading_spacing_s = core::median_spacing_s(heading_t, 1);
  imu.accel = accel;
  for (std::size_t k = 0; k < grid.size(); ++k) {
    if (!std::isfinite(psi[k])) continue;
    const std::size_t i = rows[k];
    auto v = [&](int c) { return (*cols[static_cast<std::size_t>(c)])[i]; };
    imu.t_s.push_back(grid[k]);
    imu.theta_rad.emplace_back(v(0), v(1), psi[k]);
    imu.omega_b_rps.emplace_back(v(2), v(3), v(4));
    imu.accel_b_mps2.emplace_back(v(5), v(6), v(7));
  }
  if (imu.size() < 100)
    throw core::InputError({{}, {}, {}, name + ".ax"},
                           "fewer than 100 rows carry " + name +
                               " and the heading over the same time (" +
                               std::to_string(imu.size()) + ")",
                           "log the MRU and the gyro compass over the whole maneuver");
  if (grid.size() > imu.size())
    imu.notes.push_back(std::to_string(grid.size() - imu.size()) + " " + name +
                        " samples outside the heading's time dropped");
  return imu;
}

namespace {

// The prefixes mruK of `log` that have every field of `fields`, in K order.
std::vector<std::string> mru_prefixes(const core::Log& log,
                                      std::initializer_list<const char*> fields) {
  std::vector<std::pair<int, std::string>> found;
  for (const std::string& c : log.channel_names()) {
    const auto dot = c.find('.');
    if (c.rfind("mru", 0) != 0 || dot == std::string::npos || c.substr(dot + 1) != "ax") continue;
    const std::string prefix = c.substr(0, dot);
    const std::string num = prefix.substr(3);
    if (num.empty() || !std::all_of(num.begin(), num.end(), ::isdigit)) continue;
    bool all = true;
    for (const char* f : fields) all = all && log.has(prefix + "." + f);
    if (all) found.emplace_back(std::stoi(num), prefix);
  }
  std::sort(found.begin(), found.end());
  std::vector<std::string> out;
  for (const auto& f : found) out.push_back(f.second);
  return out;
}

}  // namespace

std::vector<std::string> imu_names(const core::Log& log) {
  return mru_prefixes(log, {"roll", "pitch", "p", "q", "r", "ax", "ay", "az"});
}

std::vector<std::string> mru_accel_names(const core::Log& log) {
  return mru_prefixes(log, {"ax", "ay", "az"});
}

Eigen::Vector3d white_noise_std(const std::vector<Eigen::Vector3d>& x) {
  Eigen::Vector3d out = Eigen::Vector3d::Zero();
  const std::size_t n = x.size();
  if (n < 3) return out;
  for (int a = 0; a < 3; ++a) {
    std::vector<double> d2(n - 2);
    for (std::size_t i = 1; i + 1 < n; ++i) d2[i - 1] = x[i + 1][a] - 2.0 * x[i][a] + x[i - 1][a];
    out[a] = 1.4826 * median_abs(std::move(d2)) / std::sqrt(6.0);
  }
  return out;
}

}  // namespace dynpos::calib
