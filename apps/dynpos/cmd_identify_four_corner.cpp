// four-corner (placeholder until implemented).

#include "commands.hpp"

namespace dynpos::cli {

void add_identify_four_corner(CLI::App& identify) {
  add_planned(identify, "four-corner", "DP 4-corner: legs, durations, thrust and energy",
              "leg segmentation, accumulated thrust [kNs] and energy [kJ] (table 3.6)");
}

}  // namespace dynpos::cli
