#include "dynpos/analysis/agility_text.hpp"

#include <optional>
#include <vector>

#include "dynpos/analysis/option_text.hpp"
#include "dynpos/analysis/options.hpp"

namespace dynpos::analysis {

ident::AgilityWindow parse_agility_window(const std::string& spec) {
  const std::vector<double> v = parse_numbers(spec, "window");
  if (v.size() < 3 || v.size() > 5) {
    throw option_error("window",
                       "'" + spec + "' needs 3 to 5 numbers, has " + std::to_string(v.size()),
                       "--window T_STEP,T_END,DIR_DEG[,THRUST_PCT[,YAW_PCT]]");
  }
  ident::AgilityWindow w{v[0], v[1], v[2], v.size() > 3 ? v[3] : 100.0, std::nullopt};
  if (v.size() > 4) w.yaw_pct = v[4];
  return w;
}

ObservedCurrent parse_observed_current(const std::string& spec) {
  const std::vector<double> v = parse_numbers(spec, "current");
  if (v.size() != 2) {
    throw option_error("current", "'" + spec + "' is not SPEED,TO_DEG",
                       "e.g. --current 0.2,318 (0.2 m/s towards 318°, as observed)");
  }
  return ObservedCurrent{v[0], v[1]};
}

}  // namespace dynpos::analysis
