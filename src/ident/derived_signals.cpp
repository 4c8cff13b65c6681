#include "dynpos/ident/derived_signals.hpp"

#include <cmath>
#include <numbers>

#include "series.hpp"

namespace dynpos::ident {

std::vector<double> total_speed(std::span<const double> u_mps, std::span<const double> v_mps) {
  detail::check_same_length(u_mps.size(), v_mps.size(), "sway speed");
  std::vector<double> out(u_mps.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i] = std::sqrt(u_mps[i] * u_mps[i] + v_mps[i] * v_mps[i]);  // (3.19); NaN propagates
  }
  return out;
}

std::vector<double> yaw_rate_deg_s(std::span<const double> r_rad_s) {
  std::vector<double> out(r_rad_s.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = r_rad_s[i] * 180.0 / std::numbers::pi;
  return out;
}

void add_total_speed(core::Log& log, std::string_view u, std::string_view v, std::string name) {
  std::vector<double> values = total_speed(log.values(u), log.values(v));
  log.add_channel(std::move(name), "m/s", std::move(values));
}

void add_yaw_rate_deg_s(core::Log& log, std::string_view r, std::string name) {
  std::vector<double> values = yaw_rate_deg_s(log.values(r));
  log.add_channel(std::move(name), "deg/s", std::move(values));
}

}  // namespace dynpos::ident
