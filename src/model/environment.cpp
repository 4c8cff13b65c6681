#include "dynpos/model/environment.hpp"

#include <cmath>

#include "dynpos/core/error.hpp"

namespace dynpos::model {
namespace {

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

void require(bool ok, const char* what) {
  if (!ok) throw core::InputError({}, what);
}

// The vessel file's [current], [wind] and [bias] tables (core/param_range.hpp).
template <typename P>
std::vector<core::BasicParamField<core::ParamValue<P>>> current_fields(P& p) {
  return {
      {{"speed_std_mps", "m/s", 0, 1}, &p.speed_std_mps},
      {{"dir_std_deg", "deg", 0, 90, false, false, kDegToRad}, &p.dir_std_rad},
      {{"time_constant_s", "s", 1, 1e6}, &p.time_constant_s},
  };
}

template <typename P>
std::vector<core::BasicParamField<core::ParamValue<P>>> wind_fields(P& p) {
  return {
      {{"gust_std_fraction", "1", 0, 0.99}, &p.gust_std_fraction},
      {{"gust_time_constant_s", "s", 0.01, 1e4}, &p.gust_time_constant_s},
      {{"dir_std_deg", "deg", 0, 90, false, false, kDegToRad}, &p.dir_std_rad},
      {{"frontal_area_m2", "m²", 0.1, 1e5}, &p.frontal_area_m2},
      {{"lateral_area_m2", "m²", 0.1, 1e5}, &p.lateral_area_m2},
      {{"length_m", "m", 1, 500}, &p.length_m},
      {{"cx", "1", 0, 5}, &p.cx},
      {{"cy", "1", 0, 5}, &p.cy},
      {{"cn", "1", -1, 1}, &p.cn},
      {{"rho_air_kg_m3", "kg/m³", 0.5, 2}, &p.rho_air},
  };
}

template <typename P>
std::vector<core::BasicParamField<core::ParamValue<P>>> bias_fields(P& p) {
  return {
      {{"std_north_N", "N", 0, 1e7}, &p.std[0]},
      {{"std_east_N", "N", 0, 1e7}, &p.std[1]},
      {{"std_yaw_Nm", "N·m", 0, 1e9}, &p.std[2]},
      {{"time_constant_north_s", "s", 1, 1e6}, &p.time_constant_s[0]},
      {{"time_constant_east_s", "s", 1, 1e6}, &p.time_constant_s[1]},
      {{"time_constant_yaw_s", "s", 1, 1e6}, &p.time_constant_s[2]},
      {{"reference_hs_m", "m", 0.01, 19.99}, &p.reference_hs_m},
      {{"calm_fraction", "1", 0, 1}, &p.calm_fraction},
  };
}

// Throws core::InputError naming the key of `range` unless value is within it.
void require_in(const core::ParamRange& range, double value) {
  core::check_ranges("environment", std::vector<core::ConstParamField>{{range, &value}});
}

}  // namespace

std::vector<core::ParamField> param_fields(CurrentParams& params) { return current_fields(params); }
std::vector<core::ParamField> param_fields(WindParams& params) { return wind_fields(params); }
std::vector<core::ParamField> param_fields(BiasParams& params) { return bias_fields(params); }

void CurrentParams::validate() const {
  require_in(kCurrentSpeedRange, speed_mps);
  require(std::isfinite(to_rad), "CurrentParams.to_rad must be finite");
  core::check_ranges("current", current_fields(*this));
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
  require_in(kWindSpeedRange, speed_mps);
  require(std::isfinite(from_rad), "WindParams.from_rad must be finite");
  core::check_ranges("wind", wind_fields(*this));
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

namespace {

// The wind force for the dynamic pressure q = ½ρ_a V² [Pa] from gamma_rad off the bow.
Eigen::Vector3d wind_force_at_pressure(const WindParams& params, double q,
                                       double gamma_rad) noexcept {
  return {-params.cx * std::cos(gamma_rad) * q * params.frontal_area_m2,
          -params.cy * std::sin(gamma_rad) * q * params.lateral_area_m2,
          -params.cn * std::sin(2.0 * gamma_rad) * q * params.lateral_area_m2 * params.length_m};
}

}  // namespace

Eigen::Vector3d wind_force_b(const WindParams& params, double speed_mps,
                             double gamma_rad) noexcept {
  return wind_force_at_pressure(params, 0.5 * params.rho_air * speed_mps * speed_mps, gamma_rad);
}

Eigen::Vector3d relative_wind_force_b(const WindParams& params, double speed_mps, double from_rad,
                                      double heading_rad,
                                      const Eigen::Vector2d& velocity_n) noexcept {
  // Air velocity over ground (it blows towards from + π), minus the vessel's velocity.
  const Eigen::Vector2d air_n(-speed_mps * std::cos(from_rad), -speed_mps * std::sin(from_rad));
  const Eigen::Vector2d rel_n = air_n - velocity_n;
  const double c = std::cos(heading_rad), s = std::sin(heading_rad);
  const double ux = c * rel_n.x() + s * rel_n.y();  // relative air velocity in BODY
  const double uy = -s * rel_n.x() + c * rel_n.y();
  const double v2 = ux * ux + uy * uy;
  if (v2 == 0.0) return Eigen::Vector3d::Zero();
  // The angle the relative wind comes from, off the bow.
  return wind_force_at_pressure(params, 0.5 * params.rho_air * v2, std::atan2(-uy, -ux));
}

Eigen::Vector3d Wind::force_b(double heading_rad,
                              const Eigen::Vector2d& velocity_n) const noexcept {
  return relative_wind_force_b(params_, speed_mps(), from_rad(), heading_rad, velocity_n);
}

void BiasParams::validate() const { core::check_ranges("bias", bias_fields(*this)); }

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
