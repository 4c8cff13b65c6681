#include "dynpos/calib/motion_series.hpp"

#include <cmath>

#include "dynpos/core/error.hpp"

namespace dynpos::calib {
namespace {

core::InputError missing_role(const std::string& role) {
  return core::InputError(
      {{}, {}, {}, role}, "the lever-arm estimators need the role '" + role + "', not in the log",
      "map it with --col " + role + "=COLUMN (and --unit " + role + "=UNIT if not SI)");
}

}  // namespace

MotionFromLog motion_from_log(const core::Log& log, const MotionNeeds& needs) {
  std::vector<std::string> roles = {"roll", "pitch", "heading"};
  if (needs.angular_rate) roles.insert(roles.end(), {"p", "q", "r"});
  if (needs.velocity) roles.insert(roles.end(), {"u", "v"});
  MotionFromLog out;
  const bool heave = needs.velocity && log.has("w");
  if (needs.velocity && !heave) {
    if (!needs.heave_optional) throw missing_role("w");
    out.notes.emplace_back("w (heave speed) not logged: taken as 0");
  }
  if (heave) roles.emplace_back("w");
  std::vector<const std::vector<double>*> columns;
  for (const std::string& role : roles) {
    if (!log.has(role)) throw missing_role(role);
    columns.push_back(&log.values(role));
  }
  MotionSeries& m = out.motion;
  const std::vector<double>& t = log.time();
  for (std::size_t i = 0; i < t.size(); ++i) {
    bool complete = true;
    for (const auto* c : columns) complete = complete && std::isfinite((*c)[i]);
    if (!complete) {
      ++out.rows_skipped;
      continue;
    }
    auto at = [&](std::size_t k) { return (*columns[k])[i]; };
    m.t_s.push_back(t[i]);
    m.theta_rad.emplace_back(at(0), at(1), at(2));
    std::size_t k = 3;
    if (needs.angular_rate) {
      m.omega_b_rps.emplace_back(at(k), at(k + 1), at(k + 2));
      k += 3;
    }
    if (needs.velocity) m.v_b_mps.emplace_back(at(k), at(k + 1), heave ? at(k + 2) : 0.0);
  }
  if (m.size() < 2) {
    throw core::InputError(
        {{}, {}, {}, "time"},
        "fewer than two rows carry all of the motion channels (" + std::to_string(m.size()) + ")",
        "check that roll, pitch, heading, p, q, r, u, v are logged together");
  }
  return out;
}

}  // namespace dynpos::calib
