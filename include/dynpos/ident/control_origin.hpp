#pragma once
/// \file
/// A logged position of a point fixed in the hull (a GNSS antenna) moved to the control origin
/// (CO), where a DP system controls its position: p_CO = p − R(ψ)·l in the horizontal plane,
/// or with roll and pitch p_CO = p − R(Θ)·l (2.4) for an arm with a height (a mast antenna
/// sways with the roll and pitch by z·sin φ and z·sin θ).

#include <vector>

namespace dynpos::ident {

/// Moves north_m/east_m [m] (NED) of the point at the horizontal lever arm (arm_x_m forward,
/// arm_y_m starboard; BODY, from the CO) [m] to the CO, in place. The heading [rad] at a sample
/// is the last valid one at or before it; positions before the first valid heading become NaN.
/// NaN positions stay NaN; an arm of zero changes nothing. The series share one time axis:
/// std::invalid_argument if their lengths differ.
void move_to_control_origin(std::vector<double>& north_m, std::vector<double>& east_m,
                            const std::vector<double>& heading_rad, double arm_x_m, double arm_y_m);

/// As above with the full lever arm l = (x, y, z) BODY [m] and the attitude: the horizontal part
/// of R(φ, θ, ψ)·l (2.4) is taken off. roll_rad/pitch_rad may be empty (level: the horizontal arm
/// alone); like the heading, a missing sample holds the last valid one.
void move_to_control_origin(std::vector<double>& north_m, std::vector<double>& east_m,
                            const std::vector<double>& heading_rad,
                            const std::vector<double>& roll_rad,
                            const std::vector<double>& pitch_rad, const double (&arm_b_m)[3]);

}  // namespace dynpos::ident
