#include "dynpos/scenario/operator_commands.hpp"

#include <algorithm>
#include <utility>

#include "dynpos/core/angle.hpp"
#include "dynpos/core/log.hpp"

namespace dynpos::scenario {
namespace {

// A command is due at the first control step within this of its time (control steps are
// products k·dt, so an exact comparison could miss the step a command was written for).
constexpr double kDueSlack_s = 1e-9;

}  // namespace

JoystickSchedule::JoystickSchedule(std::vector<JoystickCommand> commands,
                                   const Eigen::Vector3d& initial_lever_pct)
    : commands_(std::move(commands)), lever_pct_(initial_lever_pct) {}

bool JoystickSchedule::advance(double t) {
  bool changed = false;
  while (next_ < commands_.size() && commands_[next_].t_s <= t + kDueSlack_s) {
    const JoystickCommand& j = commands_[next_++];
    lever_pct_ = {j.surge_pct, j.sway_pct, j.yaw_pct};
    changed = true;
  }
  return changed;
}

RudderSchedule::RudderSchedule(std::vector<RudderCommand> commands, const model::Rudder& rudder,
                               const model::Hull& hull, double x_rudder_m, double dt_s)
    : commands_(std::move(commands)),
      rudder_(rudder),
      hull_(hull),
      x_rudder_m_(x_rudder_m),
      dt_s_(dt_s) {}

const std::optional<double>& RudderSchedule::advance(double t, double rudder_before_rad,
                                                     double surge_mps) {
  while (next_ < commands_.size() && commands_[next_].t_s <= t + kDueSlack_s) {
    const RudderCommand& rc = commands_[next_++];
    const double from = override_rad_.value_or(rudder_before_rad);
    override_rad_ =
        rc.release ? std::nullopt : std::optional<double>(core::deg_to_rad(rc.angle_deg));
    if (!override_rad_) continue;
    const double max_angle = rudder_.params().max_angle;
    const double to = std::clamp(*override_rad_, -max_angle, max_angle);
    RudderStepTruth step;
    step.t_s = t;
    step.from_deg = core::rad_to_deg(from);
    step.to_deg = core::rad_to_deg(to);
    step.surge_mps = surge_mps;
    step.servo = model::rudder_step_truth(rudder_, from, to, dt_s_);
    if (surge_mps > 0.1) step.nomoto = nomoto_truth(hull_.nomoto(surge_mps, x_rudder_m_));
    steps_.push_back(step);
  }
  return override_rad_;
}

SetpointSchedule::SetpointSchedule(std::vector<SetpointCommand> setpoints,
                                   const control::OperatingCircle& circle)
    : setpoints_(std::move(setpoints)),
      circle_(circle),
      setpoint_n_(Eigen::Vector3d::Constant(core::kMissing)) {}

void SetpointSchedule::apply(const SetpointCommand& sp, double t) {
  setpoint_n_ = {sp.north_m, sp.east_m, core::deg_to_rad(sp.heading_deg)};
  if (!legs_.empty()) legs_.back().t_end_s = t;
  SetpointTruth leg;
  leg.name = sp.name;
  leg.t_start_s = t;
  leg.north_m = sp.north_m;
  leg.east_m = sp.east_m;
  leg.heading_deg = sp.heading_deg;
  legs_.push_back(leg);
  active_ = true;
}

void SetpointSchedule::advance(double t, const Eigen::Vector3d& eta_n) {
  while (next_ < setpoints_.size()) {
    const SetpointCommand& sp = setpoints_[next_];
    const bool timed = sp.t_s >= 0.0 && sp.t_s <= t + kDueSlack_s;
    const bool on_reach = sp.t_s < 0.0 && active_ && circle_.reached(eta_n, setpoint_n_);
    if (!timed && !on_reach) break;
    if (on_reach) legs_.back().t_reached_s = t;
    apply(sp, t);
    ++next_;
  }
  // The first time the setpoint in force is inside its operating circle, whether the next
  // setpoint follows on reach or at its time.
  if (active_ && !legs_.back().t_reached_s && circle_.reached(eta_n, setpoint_n_)) {
    legs_.back().t_reached_s = t;
  }
}

}  // namespace dynpos::scenario
