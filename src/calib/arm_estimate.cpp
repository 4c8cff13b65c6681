#include "dynpos/calib/arm_estimate.hpp"

namespace dynpos::calib {

std::string_view determinacy_name(Determinacy d) {
  switch (d) {
    case Determinacy::kWell:
      return "well";
    case Determinacy::kWeakly:
      return "weakly";
    case Determinacy::kNot:
      return "not";
  }
  return "not";
}

}  // namespace dynpos::calib
