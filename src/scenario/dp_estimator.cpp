#include "dynpos/scenario/dp_estimator.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "dynpos/core/angle.hpp"
#include "dynpos/core/log.hpp"
#include "dynpos/scenario/dp_task.hpp"
#include "dynpos/scenario/trial_environment.hpp"

namespace dynpos::scenario {
namespace {

using Plant = VesselPlant;
using model::Hull;

double gnss_std_m(const VesselConfig& vessel) {
  return vessel.sensors.gnss.empty() ? 0.01 : vessel.sensors.gnss.front().horizontal_std_m;
}

// The white noise of the MRU's acceleration averaged over a control period [m/s²]: its σ per
// sample at its rate over √(samples per period).
double accel_std_per_step_mps2(const VesselConfig& vessel, double period_s) {
  if (vessel.sensors.mru.empty()) return 0.0;
  const sensors::MruParams& mru = vessel.sensors.mru.front();
  return mru.accel_std_mps2 / std::sqrt(std::max(1.0, mru.timing.rate_hz * period_s));
}

double rate_std_rad_s(const VesselConfig& vessel) {
  return vessel.sensors.mru.empty() ? core::deg_to_rad(0.03)
                                    : vessel.sensors.mru.front().rate_std_rad_s;
}

}  // namespace

control::EkfObserverTuning dp_ekf_tuning(const model::WaveMotion& waves, double heading0_rad,
                                         double yaw_rate_std_rad_s) {
  const Eigen::Matrix<double, 6, 1> wf_std = waves.position_std(heading0_rad);
  const double horizontal_m = std::hypot(wf_std[0], wf_std[1]);
  control::EkfObserverTuning t;
  t.wave_motion_std.head<2>().setConstant(std::max(0.4 * horizontal_m, 0.01));
  t.bias_accel_noise.head<2>().setConstant(2e-3);
  t.position_std_m = 0.05;
  t.yaw_rate_std_rad_s = yaw_rate_std_rad_s;
  return t;
}

control::ObserverModel observer_model(const VesselConfig& vessel, const model::Hull& hull,
                                      const model::SeaStateParams& sea) {
  const control::DpControllerParams dp = dp_controller_params(vessel, hull);
  control::ObserverModel m;
  m.M = dp.M;
  m.D = dp.D;
  m.wave_peak_frequency_rad_s = model::response_peak_frequency(sea, vessel.waves);
  m.wave_variance_share =
      model::response_variance_shares(sea, vessel.waves,
                                      std::vector<double>(control::kWaveComponentRatio.begin(),
                                                          control::kWaveComponentRatio.end()));
  return m;
}

control::ObserverModel observer_model(const ScenarioSpec& spec, const VesselConfig& vessel,
                                      const model::Hull& hull) {
  return observer_model(vessel, hull, sea_state(spec.environment));
}

DpEstimator::DpEstimator(const ScenarioSpec& spec, const VesselConfig& vessel,
                         const VesselPlant& plant, std::uint64_t seed, double period_s,
                         const Eigen::Vector3d& eta0_n, const model::Wind* wind)
    : gnss_dropouts_(spec.gnss_dropouts),
      plant_(plant),
      kind_(spec.observer),
      period_s_(period_s),
      waves_(sea_state(spec.environment), vessel.waves, seed, period_s),
      north_noise_(gnss_std_m(vessel), sim::Rng(seed, "dp.gnss.north")),
      east_noise_(gnss_std_m(vessel), sim::Rng(seed, "dp.gnss.east")),
      heading_noise_(vessel.sensors.gyro.noise.noise_std, sim::Rng(seed, "dp.gyro")),
      rate_noise_(rate_std_rad_s(vessel), sim::Rng(seed, "dp.rate")),
      wind_(spec.observer_wind_feedforward ? wind : nullptr),
      wind_params_(vessel.wind),
      wind_speed_noise_(vessel.sensors.wind_speed.noise.noise_std, sim::Rng(seed, "dp.wind.speed")),
      wind_dir_noise_(vessel.sensors.wind_dir.noise.noise_std, sim::Rng(seed, "dp.wind.dir")),
      wind_period_s_(vessel.sensors.wind_speed.timing.enabled()
                         ? 1.0 / vessel.sensors.wind_speed.timing.rate_hz
                         : period_s),
      accel_x_noise_(accel_std_per_step_mps2(vessel, period_s), sim::Rng(seed, "dp.accel.x")),
      accel_y_noise_(accel_std_per_step_mps2(vessel, period_s), sim::Rng(seed, "dp.accel.y")),
      last_raw_(eta0_n) {
  if (spec.inertial_position_aid && !vessel.sensors.mru.empty()) {
    // The bridge is set to the MRU's and the GNSS receiver's stated noise (at least 1e-4 m/s²
    // and 1 mm, for a noise-free sensor's).
    const sensors::MruParams& mru = vessel.sensors.mru.front();
    control::InertialPositionTuning aid;
    aid.accel_std_mps2 = std::max(accel_std_per_step_mps2(vessel, period_s), 1e-4);
    aid.accel_bias_std_mps2 = mru.accel_bias_std_mps2;
    aid.accel_bias_time_constant_s = mru.accel_bias_time_constant_s;
    aid.position_std_m = std::max(gnss_std_m(vessel), 1e-3);
    inertial_.emplace(aid);
    for (int i = 0; i < 2 && mru.accel_bias_std_mps2 > 0.0; ++i) {
      accel_bias_[i] = sim::GaussMarkov::with_stationary_std(
          mru.accel_bias_time_constant_s, mru.accel_bias_std_mps2, period_s,
          sim::Rng(seed, i == 0 ? "dp.accel.bias.x" : "dp.accel.bias.y"));
      accel_bias_[i]->reset_stationary();
    }
  }
  const control::ObserverModel model = observer_model(spec, vessel, plant.hull());
  if (kind_ == control::ObserverKind::kPassive) {
    observer_.emplace<control::PassiveObserver>(model, control::passive_observer_gains(model),
                                                eta0_n);
  } else if (kind_ == control::ObserverKind::kEkf) {
    observer_.emplace<control::EkfObserver>(
        model, dp_ekf_tuning(waves_, eta0_n.z(), rate_std_rad_s(vessel)), eta0_n);
  }
}

Eigen::Vector3d DpEstimator::measure(double t, const sim::ConstVectorRef& x) {
  // The wave generator at the sample of t (the control grid from t = 0).
  const long k = std::lround(t / period_s_);
  if (sample_ < 0) sample_ = 0;
  for (; sample_ < k; ++sample_) waves_.advance();
  const double psi = x[Plant::kHull + Hull::kYaw];
  const model::WaveMotion6 wf = waves_.motion(psi);
  const double c = std::cos(psi), s = std::sin(psi);
  Eigen::Vector3d y(x[Plant::kHull + Hull::kNorth] + c * wf.position[0] - s * wf.position[1],
                    x[Plant::kHull + Hull::kEast] + s * wf.position[0] + c * wf.position[1],
                    psi + wf.position[5]);
  y.x() += north_noise_.sample();
  y.y() += east_noise_.sample();
  y.z() = core::wrap_2pi(y.z() + heading_noise_.sample());
  wf_velocity_b_ = Eigen::Vector3d(wf.velocity[0], wf.velocity[1], wf.velocity[5]);
  yaw_rate_ = x[Plant::kHull + Hull::kYawRate] + wf.velocity[5] + rate_noise_.sample();
  if (any_covers(gnss_dropouts_, t)) y.x() = y.y() = core::kMissing;
  if (inertial_) {
    // The MRU's levelled acceleration turned into NED by the measured heading, then the bridge.
    const Eigen::Vector2d velocity_b(x[Plant::kHull + Hull::kSurge] + wf.velocity[0],
                                     x[Plant::kHull + Hull::kSway] + wf.velocity[1]);
    const Eigen::Vector2d a_b =
        measured_acceleration_b(Eigen::Vector2d(c * velocity_b.x() - s * velocity_b.y(),
                                                s * velocity_b.x() + c * velocity_b.y()),
                                psi + wf.position[5]);
    const double cm = std::cos(y.z()), sm = std::sin(y.z());
    const Eigen::Vector2d a_n(cm * a_b.x() - sm * a_b.y(), sm * a_b.x() + cm * a_b.y());
    y.head<2>() = inertial_->step(y.head<2>(), a_n, period_s_);
  }
  return y;
}

Eigen::Vector2d DpEstimator::measured_acceleration_b(const Eigen::Vector2d& velocity_n,
                                                     double psi_rad) {
  const Eigen::Vector2d accel_n = (velocity_n - last_velocity_n_) / period_s_;
  last_velocity_n_ = velocity_n;
  if (!accel_n.allFinite()) return accel_n;
  const double c = std::cos(psi_rad), s = std::sin(psi_rad);
  Eigen::Vector2d a_b(c * accel_n.x() + s * accel_n.y() + accel_x_noise_.sample(),
                      -s * accel_n.x() + c * accel_n.y() + accel_y_noise_.sample());
  for (int i = 0; i < 2; ++i) {
    if (accel_bias_[i]) a_b[i] += accel_bias_[i]->step();
  }
  return a_b;
}

Eigen::Vector3d DpEstimator::measured_wind_force_b(double t, const sim::ConstVectorRef& x,
                                                   double psi_rad) {
  if (wind_ == nullptr) return Eigen::Vector3d::Zero();
  // The sensor samples the wind at its rate and the DP system holds the reading.
  if (t >= next_wind_sample_s_) {
    wind_speed_mps_ = std::max(wind_->speed_mps() + wind_speed_noise_.sample(), 0.0);
    wind_from_rad_ = wind_->from_rad() + wind_dir_noise_.sample();
    next_wind_sample_s_ = t + wind_period_s_ - 1e-9;
  }
  const double speed_mps = wind_speed_mps_, from_rad = wind_from_rad_;
  const double psi = x[Plant::kHull + Hull::kYaw];
  const double u = x[Plant::kHull + Hull::kSurge], v = x[Plant::kHull + Hull::kSway];
  const Eigen::Vector2d velocity_n(std::cos(psi) * u - std::sin(psi) * v,
                                   std::sin(psi) * u + std::cos(psi) * v);
  return model::relative_wind_force_b(wind_params_, speed_mps, from_rad, psi_rad, velocity_n);
}

DpMotion DpEstimator::update(double t, const sim::ConstVectorRef& x, const sim::ConstVectorRef& u) {
  DpMotion truth{x.segment<3>(Plant::kHull + Hull::kNorth),
                 x.segment<3>(Plant::kHull + Hull::kSurge)};
  if (kind_ == control::ObserverKind::kIdeal || t < 0.0) return truth;
  const Eigen::Vector3d y = measure(t, x);
  if (kind_ == control::ObserverKind::kRaw) {
    DpMotion raw{y, truth.nu_b + wf_velocity_b_};
    // The bridged position through a dropout (the bridge is upstream of any wave filter); past
    // it, or without it, the last position is held. The heading stays continuous.
    raw.eta_n.z() = truth.eta_n.z() + core::wrap_pi(y.z() - truth.eta_n.z());
    if (std::isnan(y.x())) raw.eta_n.head<2>() = last_raw_.head<2>();
    last_raw_ = raw.eta_n;
    return raw;
  }
  // The thrust feedback and, with the wind given, the wind force from the wind sensor at the
  // measured heading.
  wind_force_b_ = measured_wind_force_b(t, x, y.z());
  const Eigen::Vector3d tau_b =
      plant_.actuators(x, u.segment<2>(Plant::kCurrentNed)).tau_b + wind_force_b_;
  return std::visit(
      [&](auto& o) -> DpMotion {
        if constexpr (std::is_same_v<std::decay_t<decltype(o)>, std::monostate>) {
          return truth;
        } else {
          if constexpr (std::is_same_v<std::decay_t<decltype(o)>, control::EkfObserver>) {
            o.step(y, tau_b, period_s_, yaw_rate_);
          } else {
            o.step(y, tau_b, period_s_);
          }
          return {o.estimate().eta_n, o.estimate().nu_b};
        }
      },
      observer_);
}

bool DpEstimator::position_bridged() const noexcept { return inertial_ && inertial_->bridging(); }

std::optional<control::ObserverEstimate> DpEstimator::estimate() const {
  std::optional<control::ObserverEstimate> e;
  if (const auto* o = std::get_if<control::PassiveObserver>(&observer_)) e = o->estimate();
  if (const auto* o = std::get_if<control::EkfObserver>(&observer_)) e = o->estimate();
  if (e) {
    // The whole environmental load: b̂ and the wind force fed forward, in NED.
    const double c = std::cos(e->eta_n.z()), s = std::sin(e->eta_n.z());
    e->bias_n += Eigen::Vector3d(c * wind_force_b_.x() - s * wind_force_b_.y(),
                                 s * wind_force_b_.x() + c * wind_force_b_.y(), wind_force_b_.z());
  }
  return e;
}

}  // namespace dynpos::scenario
