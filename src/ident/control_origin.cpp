#include "dynpos/ident/control_origin.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dynpos::ident {

void move_to_control_origin(std::vector<double>& north_m, std::vector<double>& east_m,
                            const std::vector<double>& heading_rad, double arm_x_m,
                            double arm_y_m) {
  move_to_control_origin(north_m, east_m, heading_rad, {}, {}, {arm_x_m, arm_y_m, 0.0});
}

void move_to_control_origin(std::vector<double>& north_m, std::vector<double>& east_m,
                            const std::vector<double>& heading_rad,
                            const std::vector<double>& roll_rad,
                            const std::vector<double>& pitch_rad, const double (&arm_b_m)[3]) {
  const double x = arm_b_m[0], y = arm_b_m[1], z = arm_b_m[2];
  if (x == 0.0 && y == 0.0 && z == 0.0) return;
  const std::size_t n = north_m.size();
  if (east_m.size() != n || heading_rad.size() != n ||
      (!roll_rad.empty() && roll_rad.size() != n) ||
      (!pitch_rad.empty() && pitch_rad.size() != n)) {
    throw std::invalid_argument("move_to_control_origin: the series differ in length");
  }
  // Held from the last valid sample; level without roll and pitch.
  double psi = std::nan(""), phi = 0.0, theta = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isnan(heading_rad[i])) psi = heading_rad[i];
    if (i < roll_rad.size() && !std::isnan(roll_rad[i])) phi = roll_rad[i];
    if (i < pitch_rad.size() && !std::isnan(pitch_rad[i])) theta = pitch_rad[i];
    const double cf = std::cos(phi), sf = std::sin(phi), ct = std::cos(theta), st = std::sin(theta),
                 cp = std::cos(psi), sp = std::sin(psi);
    // The first two rows of R(Θ) (2.4) times l.
    north_m[i] -= cp * ct * x + (-sp * cf + cp * st * sf) * y + (sp * sf + cp * cf * st) * z;
    east_m[i] -= sp * ct * x + (cp * cf + sf * st * sp) * y + (-cp * sf + st * sp * cf) * z;
  }
}

}  // namespace dynpos::ident
