#include "dynpos/hybrid/jump_set.hpp"

namespace dynpos::hybrid {

const char* to_string(JumpSet jump_set) noexcept {
  switch (jump_set) {
    case JumpSet::kNone:
      return "none";
    case JumpSet::kIdeal:
      return "ideal";
    case JumpSet::kSampled:
      return "sampled";
  }
  return "unknown";
}

}  // namespace dynpos::hybrid
