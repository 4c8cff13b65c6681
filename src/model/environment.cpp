#include "dynpos/model/environment.hpp"

#include <cmath>
#include <stdexcept>

namespace dynpos::model {
namespace {

void require(bool ok, const char* what) {
  if (!ok) throw std::invalid_argument(what);
}

}  // namespace

void CurrentParams::validate() const {
  require(speed_mps >= 0 && speed_mps <= 3, "CurrentParams.speed_mps must be in [0, 3] m/s");
  require(std::isfinite(to_rad), "CurrentParams.to_rad must be finite");
  require(speed_std_mps >= 0 && dir_std_rad >= 0, "CurrentParams stds must be >= 0");
  require(time_constant_s > 0, "CurrentParams.time_constant_s must be > 0");
}

Current::Current(const CurrentParams& params, std::uint64_t seed, double dt_s)
    : params_((params.validate(), params)),
      speed_(sim::GaussMarkov::with_stationary_std(params.time_constant_s, params.speed_std_mps,
                                                   dt_s, sim::Rng(seed, "current.speed"))),
      direction_(sim::GaussMarkov::with_stationary_std(params.time_constant_s, params.dir_std_rad,
                                                       dt_s, sim::Rng(seed, "current.dir"))) {
  speed_.reset_stationary();
  direction_.reset_stationary();
}

void Current::step() noexcept {
  speed_.step();
  direction_.step();
}

Eigen::Vector2d Current::velocity_n() const noexcept {
  const double speed = std::max(0.0, params_.speed_mps + speed_.value());
  const double to = params_.to_rad + direction_.value();
  return {speed * std::cos(to), speed * std::sin(to)};
}

void WindParams::validate() const {
  require(speed_mps >= 0 && speed_mps <= 50, "WindParams.speed_mps must be in [0, 50] m/s");
  require(std::isfinite(from_rad), "WindParams.from_rad must be finite");
  require(gust_std_fraction >= 0 && gust_std_fraction < 1,
          "WindParams.gust_std_fraction must be in [0, 1)");
  require(gust_time_constant_s > 0, "WindParams.gust_time_constant_s must be > 0");
  require(dir_std_rad >= 0, "WindParams.dir_std_rad must be >= 0");
  require(frontal_area_m2 > 0 && lateral_area_m2 > 0 && length_m > 0,
          "WindParams areas and length must be > 0");
  require(cx >= 0 && cy >= 0 && std::isfinite(cn), "WindParams coefficients must be >= 0");
  require(rho_air > 0, "WindParams.rho_air must be > 0");
}

Wind::Wind(const WindParams& params, std::uint64_t seed, double dt_s)
    : params_((params.validate(), params)),
      gust_(sim::GaussMarkov::with_stationary_std(params.gust_time_constant_s,
                                                  params.gust_std_fraction * params.speed_mps, dt_s,
                                                  sim::Rng(seed, "wind.gust"))),
      direction_(sim::GaussMarkov::with_stationary_std(
          params.gust_time_constant_s, params.dir_std_rad, dt_s, sim::Rng(seed, "wind.dir"))) {
  gust_.reset_stationary();
  direction_.reset_stationary();
}

void Wind::step() noexcept {
  gust_.step();
  direction_.step();
}

double Wind::speed_mps() const noexcept { return std::max(0.0, params_.speed_mps + gust_.value()); }

double Wind::from_rad() const noexcept { return params_.from_rad + direction_.value(); }

Eigen::Vector3d Wind::force_b(double heading_rad,
                              const Eigen::Vector2d& velocity_n) const noexcept {
  const double speed = speed_mps();
  const double from = from_rad();
  // Air velocity over ground (it blows towards from + π), minus the vessel's velocity.
  const Eigen::Vector2d air_n(-speed * std::cos(from), -speed * std::sin(from));
  const Eigen::Vector2d rel_n = air_n - velocity_n;
  const double c = std::cos(heading_rad), s = std::sin(heading_rad);
  const double ux = c * rel_n.x() + s * rel_n.y();  // relative air velocity in BODY
  const double uy = -s * rel_n.x() + c * rel_n.y();
  const double v2 = ux * ux + uy * uy;
  if (v2 == 0.0) return Eigen::Vector3d::Zero();
  const double gamma = std::atan2(-uy, -ux);  // angle the relative wind comes from, off the bow
  const double q = 0.5 * params_.rho_air * v2;
  return {-params_.cx * std::cos(gamma) * q * params_.frontal_area_m2,
          -params_.cy * std::sin(gamma) * q * params_.lateral_area_m2,
          -params_.cn * std::sin(2.0 * gamma) * q * params_.lateral_area_m2 * params_.length_m};
}

void BiasParams::validate() const {
  require((std.array() >= 0).all() && std.allFinite(), "BiasParams.std must be >= 0");
  require((time_constant_s.array() > 0).all(), "BiasParams.time_constant_s must be > 0");
  require(reference_hs_m > 0 && reference_hs_m < 20,
          "BiasParams.reference_hs_m must be in (0, 20) m");
  require(calm_fraction >= 0 && calm_fraction <= 1, "BiasParams.calm_fraction must be in [0, 1]");
}

double BiasParams::sea_state_factor(double hs_m) const noexcept {
  const double h = hs_m / reference_hs_m;
  const double c2 = calm_fraction * calm_fraction;
  return std::sqrt(c2 + (1.0 - c2) * (h * h) * (h * h));
}

BiasParams bias_for_sea_state(const BiasParams& params, double hs_m) {
  params.validate();
  require(hs_m >= 0 && std::isfinite(hs_m), "bias_for_sea_state: Hs must be finite and >= 0");
  BiasParams scaled = params;
  scaled.std *= params.sea_state_factor(hs_m);
  return scaled;
}

Bias::Bias(const BiasParams& params, std::uint64_t seed, double dt_s) {
  params.validate();
  const char* names[3] = {"bias.north", "bias.east", "bias.yaw"};
  for (int i = 0; i < 3; ++i) {
    axes_.push_back(sim::GaussMarkov::with_stationary_std(params.time_constant_s[i], params.std[i],
                                                          dt_s, sim::Rng(seed, names[i])));
    axes_.back().reset_stationary();
  }
}

void Bias::step() noexcept {
  for (sim::GaussMarkov& axis : axes_) axis.step();
}

Eigen::Vector3d Bias::value_n() const noexcept {
  return {axes_[0].value(), axes_[1].value(), axes_[2].value()};
}

Eigen::Vector3d step_loads_n(const std::vector<StepLoad>& loads, double t_s) noexcept {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const StepLoad& load : loads) {
    if (t_s >= load.t_on_s && t_s < load.t_off_s) sum += load.force_n;
  }
  return sum;
}

}  // namespace dynpos::model
