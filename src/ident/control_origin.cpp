#include "dynpos/ident/control_origin.hpp"

#include <algorithm>
#include <cmath>

namespace dynpos::ident {

void move_to_control_origin(std::vector<double>& north_m, std::vector<double>& east_m,
                            const std::vector<double>& heading_rad, double arm_x_m,
                            double arm_y_m) {
  if (arm_x_m == 0.0 && arm_y_m == 0.0) return;
  const std::size_t n = std::min({north_m.size(), east_m.size(), heading_rad.size()});
  double psi = std::nan("");  // held from the last valid sample
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isnan(heading_rad[i])) psi = heading_rad[i];
    north_m[i] -= std::cos(psi) * arm_x_m - std::sin(psi) * arm_y_m;
    east_m[i] -= std::sin(psi) * arm_x_m + std::cos(psi) * arm_y_m;
  }
}

}  // namespace dynpos::ident
