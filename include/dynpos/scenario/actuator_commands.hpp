#pragma once
/// \file
/// The commands the control task hands to the vessel's actuators, and their dead times: each
/// command reaches its actuator's servo loop a fixed dead time after it was given (the vessel
/// file's dead_time of each actuator, thesis tables 3.23–3.36), sampled every simulator tick.

#include <vector>

#include "dynpos/model/delay_line.hpp"
#include "dynpos/scenario/vessel_config.hpp"
#include "dynpos/sim/hybrid_system.hpp"

namespace dynpos::scenario {

/// Actuator commands before their dead times.
struct ActuatorCommands {
  double n_port_rps = 0.0;       ///< port propeller shaft speed [rps]
  double n_stb_rps = 0.0;        ///< starboard propeller shaft speed [rps]
  double rudder_port_rad = 0.0;  ///< port rudder angle [rad]
  double rudder_stb_rad = 0.0;   ///< starboard rudder angle [rad]
  double n_tunnel_rps = 0.0;     ///< tunnel thruster shaft speed [rps]
  /// A [[thruster]] layout's orders, one per unit in layout order (the fields above then 0);
  /// empty for the model's own units.
  struct Unit {
    double n_rps = 0.0;      ///< shaft speed [rps]
    double angle_rad = 0.0;  ///< azimuth direction α or rudder angle δ [rad]; 0 for the others
    double thrust_N = 0.0;   ///< the thrust allocated [N] (signed as the unit's thrust)
  };
  std::vector<Unit> units;
};

/// The dead times of the five actuator commands, or of each layout unit's shaft speed and
/// steering (model::DelayLine each).
class ActuatorDelays {
 public:
  /// Dead times of `vessel` on a tick of dt_s [s], every line filled with `initial` (the
  /// commands held before the run).
  ActuatorDelays(const VesselConfig& vessel, double dt_s, const ActuatorCommands& initial);

  /// One tick: pushes `commands` and writes the delayed ones into the plant's command inputs
  /// (VesselPlant::kCmdPort … kCmdTunnel, or a layout's from kCmdUnits) of the held input u.
  void step(const ActuatorCommands& commands, sim::VectorRef u);

 private:
  model::DelayLine port_, stb_, rudder_port_, rudder_stb_, tunnel_;
  std::vector<model::DelayLine> unit_n_, unit_angle_;  // a layout's, per unit
};

}  // namespace dynpos::scenario
