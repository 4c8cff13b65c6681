#pragma once
// The vessel's full 6-DOF motion from the plant's low-frequency state and the wave-frequency
// motion: what the sensors see.

#include <Eigen/Core>

#include "dynpos/model/sea_state.hpp"
#include "dynpos/sensors/rigid_body_motion.hpp"

namespace dynpos::scenario::detail {

/// Composes the low-frequency hull state x_hull (hull.hpp, 10 states) and its derivative with
/// the wave-frequency motion wf. WF surge/sway/heave are displacements along the LF heading's
/// axes; WF roll/pitch/yaw add to the Euler angles. Position, velocity and acceleration are
/// differentiated analytically, so (4.2) and (4.65) hold exactly along the sampled trajectory.
sensors::RigidBodyMotion compose_motion(const Eigen::Ref<const Eigen::VectorXd>& x_hull,
                                        const Eigen::Ref<const Eigen::VectorXd>& dx_hull,
                                        const model::WaveMotion6& wf);

}  // namespace dynpos::scenario::detail
