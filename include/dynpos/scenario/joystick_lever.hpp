#pragma once
/// \file
/// The joystick's lever characteristic: lever deflection in % of full (what an operator sets and
/// the trial's step tables call the step magnitude) to the force and moment demand, as a
/// fraction of the joystick's maxima, handed to the thrust allocation.
///
/// The horizontal lever is one vector (surge, sway): its direction is kept and its magnitude r
/// (= 1 at full deflection along an axis) is shaped by r^(e−1), so a demand along an axis is
/// sign(p)·|p|^e. The yaw twist has its own curve, sign(p)·|p|^e. e = 1 is a linear lever;
/// e = 2 makes a pure surge lever a shaft-speed command, because the allocation then asks each
/// main propeller for c·(p·n_max)², which it gets at n = p·n_max (thrust map (3.1)).

#include <Eigen/Core>

namespace dynpos::scenario {

/// Force and moment demand as fractions of the joystick maxima for a lever (surge, sway, yaw)
/// in % of full deflection, each in [−100, 100]; the result is clamped to [−1, 1] per axis.
/// `exponent` is the lever curve's e ≥ 1.
Eigen::Vector3d lever_to_demand_fraction(const Eigen::Vector3d& lever_pct, double exponent);

/// The inverse along one axis: the lever deflection [%] that demands `fraction` (in [−1, 1]) of
/// the maximum when the other horizontal axis is at zero, sign(f)·100·|f|^(1/e).
double lever_pct_for_fraction(double fraction, double exponent);

}  // namespace dynpos::scenario
