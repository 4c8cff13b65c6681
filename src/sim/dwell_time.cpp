#include "dynpos/sim/dwell_time.hpp"

#include <cmath>
#include <stdexcept>

namespace dynpos::sim {

DwellTime::DwellTime(double dwell_s, double slack_s) : dwell_(dwell_s), slack_(slack_s) {
  if (!(std::isfinite(dwell_s) && dwell_s >= 0.0)) {
    throw std::invalid_argument("DwellTime: the dwell time must be finite and >= 0");
  }
  if (!(std::isfinite(slack_s) && slack_s >= 0.0)) {
    throw std::invalid_argument("DwellTime: the slack must be finite and >= 0");
  }
}

}  // namespace dynpos::sim
