#pragma once
/// \file
/// Which jump set D a hybrid integral action uses (thesis chapter 5).

namespace dynpos::hybrid {

/// The jump set of a hybrid integral action.
enum class JumpSet {
  kNone,     ///< D = ∅: the conventional (continuous) integral action, no jumps
  kIdeal,    ///< the jump set of the theorem, which uses the unknown integral error
             ///< ((5.20) first order, (5.54)–(5.55) DP)
  kSampled,  ///< the practical jump set, with the integral error estimated from a sampled,
             ///< noisy state derivative ((5.30)–(5.31) first order, (5.64)–(5.67) DP)
};

/// "none", "ideal" or "sampled".
const char* to_string(JumpSet jump_set) noexcept;

}  // namespace dynpos::hybrid
