// thrust-map (placeholder until implemented).

#include "commands.hpp"

namespace dynpos::cli {

void add_identify_thrust_map(CLI::App& identify) {
  add_planned(identify, "thrust-map",
              "Thrust map: back-calculate c+ and c- of T = c n|n| (3.17), or apply a map",
              "back-calculation (3.17) and the mean coefficient (3.18)");
}

}  // namespace dynpos::cli
