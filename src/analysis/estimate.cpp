#include "dynpos/analysis/estimate.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "dynpos/analysis/control_origin_track.hpp"
#include "dynpos/analysis/data_dir.hpp"
#include "dynpos/analysis/inertial_bridge.hpp"
#include "dynpos/analysis/options.hpp"
#include "dynpos/core/samples.hpp"
#include "dynpos/model/hull.hpp"
#include "dynpos/model/sea_state.hpp"
#include "dynpos/scenario/dp_estimator.hpp"
#include "dynpos/scenario/vessel_config.hpp"
#include "leverarm_mru_roles.hpp"

namespace dynpos::analysis {
namespace {

// The roles estimate reads; of the MRUs' accelerations only the bridge's (every MRU's for
// "auto", none for "none": EstimateRequest::mru).
RoleFilter wanted_roles(const std::string& mru) {
  return [mru](const std::string& role) {
    for (const char* r : {"north", "east", "lat", "lon", "heading", "roll", "pitch"}) {
      if (role == r) return true;
    }
    for (const char* prefix : {"thrust.", "rudder.", "azimuth."}) {
      if (role.rfind(prefix, 0) == 0) return true;
    }
    return detail::is_mru_accel_role(role) && (mru == "auto" || role.rfind(mru + ".", 0) == 0);
  };
}

// Whether the log has `role` with a valid sample.
bool has_channel(const core::Log& log, const std::string& role) {
  return log.has(role) && core::has_valid_sample(log.values(role));
}

// The channel of `role`, required with a valid sample: else an error naming the role.
const std::vector<double>& required(const EstimateRequest& q, const core::Log& log,
                                    const std::string& role, const std::string& unit_name,
                                    const std::string& vessel) {
  if (has_channel(log, role)) return log.values(role);
  throw q.source.error(
      role,
      fmt::format("no {} of unit '{}' of {} ({}) with a valid sample in the log",
                  role.rfind("thrust.", 0) == 0 ? "thrust" : "angle", unit_name, vessel, role),
      fmt::format("map it (--col {}=COLUMN), or give the vessel whose units the log has "
                  "(--vessel FILE)",
                  role));
}

// τ_b at each row from every unit's thrust and angle held (observer_run.hpp's hold); NaN where
// one of them is missing. Into `in`, with the time of each row's oldest sample.
void thrust_series(const EstimateRequest& q, const core::Log& log,
                   const scenario::ThrustFeedback& feedback, const std::string& vessel,
                   control::ObserverInputs& in) {
  const std::size_t n_units = feedback.channels().size();
  std::vector<core::HeldSamples> thrust, angle;
  for (const scenario::FeedbackChannel& c : feedback.channels()) {
    thrust.push_back(core::hold_samples(log.time(), required(q, log, c.thrust_role, c.unit, vessel),
                                        q.max_hold_s));
    angle.push_back(c.angle_role.empty()
                        ? core::HeldSamples{std::vector<double>(log.size(), 0.0), log.time()}
                        : core::hold_samples(log.time(),
                                             required(q, log, c.angle_role, c.unit, vessel),
                                             q.max_hold_s));
  }
  in.tau_b.assign(log.size(), Eigen::Vector3d::Constant(core::kMissing));
  in.tau_sampled_s.assign(log.size(), core::kMissing);
  std::vector<double> t(n_units), a(n_units);
  for (std::size_t i = 0; i < log.size(); ++i) {
    double oldest = log.time()[i];
    for (std::size_t k = 0; k < n_units; ++k) {
      t[k] = thrust[k].value[i], a[k] = angle[k].value[i];
      oldest = std::min({oldest, thrust[k].sampled_s[i], angle[k].sampled_s[i]});
    }
    const bool complete =
        std::none_of(t.begin(), t.end(), [](double v) { return std::isnan(v); }) &&
        std::none_of(a.begin(), a.end(), [](double v) { return std::isnan(v); });
    if (!complete) continue;
    in.tau_b[i] = feedback.tau_b(t, a);
    in.tau_sampled_s[i] = oldest;
  }
}

// The first of NAME.ax, .ay, .az without a valid sample in the log; empty: none.
std::string missing_accel(const core::Log& log, const std::string& name) {
  for (const char* axis : {".ax", ".ay", ".az"}) {
    if (!has_channel(log, name + axis)) return name + axis;
  }
  return "";
}

// The vessel's MRU the request bridges on, or none (EstimateRequest::mru).
const sensors::MruParams* bridge_mru(const EstimateRequest& q, const core::Log& log,
                                     const scenario::VesselConfig& vessel) {
  if (q.mru == "none") return nullptr;
  const bool attitude = has_channel(log, "roll") && has_channel(log, "pitch");
  const std::vector<sensors::MruParams>& mrus = vessel.sensors.mru;
  if (q.mru == "auto") {
    if (!attitude) return nullptr;
    const auto it = std::find_if(mrus.begin(), mrus.end(), [&](const sensors::MruParams& m) {
      return missing_accel(log, m.name).empty();
    });
    return it == mrus.end() ? nullptr : &*it;
  }
  const auto it = std::find_if(mrus.begin(), mrus.end(),
                               [&](const sensors::MruParams& m) { return m.name == q.mru; });
  if (it == mrus.end()) {
    throw option_error("mru", "the vessel " + vessel.name + " has no MRU '" + q.mru + "'",
                       "auto, none, or the name of one of its [mruK] tables");
  }
  if (const std::string role = missing_accel(log, it->name); !role.empty()) {
    throw q.source.error(role, "no " + role + " with a valid sample in the log for the bridge",
                         "map it (--col " + role + "=COLUMN), or --mru none");
  }
  if (!attitude) {
    throw q.source.error("roll/pitch", "the bridge on " + it->name + " needs roll and pitch",
                         "map roll and pitch (e.g. --col roll=" + it->name +
                             ".roll --col pitch=" + it->name + ".pitch), or --mru none");
  }
  return &*it;
}

// The control origin's fixes with the GNSS gaps bridged on `mru` (inertial_bridge.hpp).
BridgedTrack bridged_track(const EstimateRequest& q, const core::Log& log,
                           const scenario::VesselConfig& vessel, const sensors::MruParams& mru,
                           const ControlOriginTrack& co) {
  BridgeSeries s;
  s.t_s = log.time();
  s.north_m = co.north_m;
  s.east_m = co.east_m;
  s.heading_rad = co.heading_rad;
  s.roll_rad = log.values("roll");
  s.pitch_rad = log.values("pitch");
  const auto &ax = log.values(mru.name + ".ax"), &ay = log.values(mru.name + ".ay"),
             &az = log.values(mru.name + ".az");
  s.accel_b.resize(log.size());
  for (std::size_t i = 0; i < log.size(); ++i) s.accel_b[i] = {ax[i], ay[i], az[i]};
  control::InertialPositionTuning tuning;
  tuning.accel_std_mps2 = std::max(mru.accel_std_mps2, 1e-4);  // per logged sample
  // At least the class's 2e-3 m/s²: the logged attitude's error leaks gravity into the
  // levelled reading (0.01°: 1.7e-3 m/s²), for the filter to learn from the fixes.
  tuning.accel_bias_std_mps2 =
      std::max(mru.accel_bias_std_mps2, control::InertialPositionTuning{}.accel_bias_std_mps2);
  tuning.accel_bias_time_constant_s = mru.accel_bias_time_constant_s;
  tuning.position_std_m = std::max(
      vessel.sensors.gnss.empty() ? 0.01 : vessel.sensors.gnss.front().horizontal_std_m, 1e-3);
  BridgedTrack bridged = bridge_gnss_gaps(s, mru.lever_arm_b, tuning, q.max_hold_s);
  // A vessel's mean acceleration over a log is ≈ 0 (5 m/s gained in 10 min: 0.008 m/s²); the
  // levelled reading's far above it when roll and pitch do not fit it (a wrong unit, another
  // sensor's angles, a reading already levelled), and a bridge on it would drift by metres.
  // Downwards the mean is 0 (kinematic) or −g (specific force) within the heave's; 0.5 m/s² is
  // an attitude some 4° off on average.
  constexpr double kLargestMeanAccel_mps2 = 0.05, kLargestDownOffset_mps2 = 0.5;
  const double down = bridged.mean_down_accel_mps2;
  if (bridged.mean_horizontal_accel_mps2 > kLargestMeanAccel_mps2 ||
      std::min(std::abs(down), std::abs(down + 9.81)) > kLargestDownOffset_mps2) {
    throw q.source.error(
        "roll/pitch",
        fmt::format("{}'s acceleration turned by the logged roll, pitch and heading averages "
                    "{:.3f} m/s² horizontally and {:.2f} m/s² down over the log (a vessel's: "
                    "about 0, and 0 or -9.81): the attitude does not fit the readings",
                    mru.name, bridged.mean_horizontal_accel_mps2, down),
        "map the MRU's own roll and pitch in their units (e.g. --col roll=" + mru.name +
            ".roll --col pitch=" + mru.name + ".pitch), or --mru none");
  }
  return bridged;
}

// The observer's model for the vessel and the operator's T_p.
control::ObserverModel observer_model(const scenario::VesselConfig& vessel, double tp_s) {
  model::SeaStateParams sea;
  sea.tp_s = tp_s;
  return scenario::observer_model(vessel, model::Hull(vessel.hull), sea);
}

}  // namespace

void EstimateRequest::validate() const {
  if (!vessel.empty() && !std::filesystem::is_regular_file(vessel)) {
    throw option_error("vessel", "'" + vessel.string() + "' is not a file",
                       "give a vessel TOML file (docs/vessel-file.md)");
  }
  if (arm_m && !arm_m->allFinite()) {
    throw option_error("arm", "the antenna lever arm is not finite", "give X,Y[,Z] in metres");
  }
  const auto kind = control::parse_observer(observer);
  if (!kind || (*kind != control::ObserverKind::kPassive && *kind != control::ObserverKind::kEkf)) {
    throw option_error("observer",
                       fmt::format("the observer must be passive or ekf, got '{}'", observer),
                       "passive (Fossen & Strand's) or ekf (the extended Kalman filter)");
  }
  const core::ParamRange& tp = model::kPeakPeriodRange;
  if (!(tp_s >= tp.lo && tp_s <= tp.hi)) {
    throw option_error(
        "tp",
        fmt::format("the wave peak period must be from {:g} to {:g} s, got {}", tp.lo, tp.hi, tp_s),
        "the sea's peak period, e.g. 8");
  }
  if (!(rate_hz >= 0.1 && rate_hz <= 100.0)) {
    throw option_error(
        "rate", fmt::format("the observer's rate must be from 0.1 to 100 Hz, got {}", rate_hz),
        "e.g. 10, a DP system's");
  }
  if (!(std::isfinite(max_hold_s) && max_hold_s > 0.0)) {
    throw option_error("max_hold",
                       fmt::format("the longest hold must be > 0 s, got {}", max_hold_s), "e.g. 5");
  }
  if (mru.empty()) {
    throw option_error("mru", "no MRU named", "auto, none, or the name of a vessel's [mruK]");
  }
  if (!(std::isfinite(settle_s) && settle_s >= 0.0)) {
    throw option_error("settle", fmt::format("the settling time must be ≥ 0 s, got {}", settle_s),
                       "e.g. 120");
  }
}

control::ObserverRunOptions EstimateRequest::run_options() const {
  validate();
  control::ObserverRunOptions o;
  o.kind = *control::parse_observer(observer);
  o.rate_hz = rate_hz;
  o.max_hold_s = max_hold_s;
  return o;
}

std::optional<BiasSummary> summarise_bias(const control::ObserverTrack& track, double from_s) {
  BiasSummary s;
  s.from_s = from_s;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero(), sum2 = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < track.t_s.size(); ++k) {
    if (track.t_s[k] < from_s) continue;
    const Eigen::Vector3d& b = track.estimate[k].bias_n;
    sum += b;
    sum2 += b.cwiseProduct(b);
    ++s.samples;
    s.to_s = track.t_s[k];
  }
  if (s.samples == 0) return std::nullopt;
  const double n = static_cast<double>(s.samples);
  s.mean_n = sum / n;
  s.std_n = (sum2 / n - s.mean_n.cwiseProduct(s.mean_n)).cwiseMax(0.0).cwiseSqrt();
  return s;
}

EstimateReport run_estimate(const EstimateRequest& q) {
  const control::ObserverRunOptions run = q.run_options();  // validates
  const scenario::VesselConfig vessel =
      scenario::load_vessel_config(vessel_file_or_default(q.vessel));
  LogSource source = q.source;
  source.window_from_s = q.t_from_s;
  source.window_to_s = q.t_to_s;
  LoadedLog loaded = source.load(wanted_roles(q.mru));
  const core::Log& log = loaded.log;
  EstimateReport r;
  r.log = q.source.log;
  r.input = std::move(loaded.input);
  r.vessel = vessel.name;
  r.vessel_source = q.vessel.empty() ? "" : q.vessel.string();
  r.arm_m = q.arm_m;
  r.observer = run.kind;
  r.tp_s = q.tp_s;
  r.run = run;
  r.settle_s = q.settle_s;
  r.csv = q.out;
  const scenario::ThrustFeedback feedback(vessel);
  r.units = feedback.channels();
  ControlOriginTrack co = control_origin_track(q.source, log, q.arm_m);
  if (!co.has_heading) {
    throw q.source.error("heading", "the observer needs the heading: none in the log",
                         "map heading (--col heading=COLUMN)");
  }
  r.position = co.position;
  r.attitude = co.attitude;
  if (const sensors::MruParams* mru = bridge_mru(q, log, vessel)) {
    BridgedTrack bridged = bridged_track(q, log, vessel, *mru, co);
    r.bridge_mru = mru->name;
    r.bridge_arm_m = mru->lever_arm_b;
    r.bridged_rows = bridged.bridged_rows;
    r.longest_gap_bridged_s = bridged.longest_gap_bridged_s;
    co.north_m = std::move(bridged.north_m);
    co.east_m = std::move(bridged.east_m);
  }
  control::ObserverInputs in;
  thrust_series(q, log, feedback, vessel.name, in);
  in.t_s = log.time();
  in.north_m = std::move(co.north_m);
  in.east_m = std::move(co.east_m);
  in.heading_rad = std::move(co.heading_rad);
  const control::ObserverModel model = observer_model(vessel, q.tp_s);
  r.wave_peak_frequency_rad_s = model.wave_peak_frequency_rad_s;
  try {
    r.track = control::run_observer(model, in, run);
  } catch (const std::invalid_argument& e) {
    std::string problem = e.what();
    if (problem.rfind("observer run: ", 0) == 0) problem.erase(0, 14);
    throw q.source.error("north/east/heading/thrust", problem,
                         "the observer starts where the log has a position, a heading and every "
                         "unit's feedback, and needs at least one step after that");
  }
  r.bias = summarise_bias(r.track, r.track.start_s + q.settle_s);
  return r;
}

}  // namespace dynpos::analysis
