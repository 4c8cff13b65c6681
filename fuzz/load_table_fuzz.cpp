// libFuzzer target: the load table of `capability --loads` (read_load_table), and the factor
// of its first rows on a small layout: every factor finite and within [0, 100].

#include <cmath>
#include <cstdlib>

#include "dynpos/capability/feasibility.hpp"
#include "dynpos/capability/load_table.hpp"
#include "dynpos/core/error.hpp"
#include "fuzz_input.hpp"

namespace {

dynpos::model::LayoutAllocator layout() {
  std::vector<dynpos::model::ThrusterUnit> units(3);
  units[0].name = "bow";
  units[0].type = dynpos::model::UnitType::kTunnel;
  units[0].x_m = 30.0;
  units[0].max_thrust_N = 1e5;
  units[0].max_reverse_thrust_N = 1e5;
  units[1].name = "az";
  units[1].x_m = -30.0;
  units[1].y_m = -5.0;
  units[1].max_thrust_N = 3e5;
  units[1].forbidden_deg = {{60.0, 120.0}};
  units[2].name = "prop";
  units[2].type = dynpos::model::UnitType::kPropellerRudder;
  units[2].x_m = -30.0;
  units[2].y_m = 5.0;
  units[2].max_thrust_N = 2e5;
  units[2].max_reverse_thrust_N = 1e5;
  units[2].rudder_lift_per_thrust = 0.6;
  return dynpos::model::LayoutAllocator(units);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static dynpos::fuzz::InputFile file("loads.csv");
  static const dynpos::model::LayoutAllocator allocator = layout();
  std::vector<dynpos::capability::LoadCase> loads;
  try {
    loads = dynpos::capability::read_load_table(file.write(dynpos::fuzz::as_text(data, size)));
  } catch (const dynpos::core::InputError&) {
    return 0;
  }
  const auto cases = dynpos::capability::failure_cases(allocator.units());
  for (std::size_t k = 0; k < loads.size() && k < 2; ++k) {
    const auto p = dynpos::capability::feasibility(allocator, loads[k], cases[k % cases.size()]);
    if (!std::isfinite(p.load_factor) || p.load_factor < 0.0 ||
        p.load_factor > dynpos::capability::kMaxLoadFactor) {
      std::abort();
    }
  }
  return 0;
}
