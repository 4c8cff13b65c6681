#pragma once
/// \file
/// How an identification fit reports its outcome: a status, a message, warnings as data, and
/// estimates with an optional standard deviation.
///
/// A fit never crashes on data it cannot use well: "did not converge", "steady state not
/// reached" or "poor fit" come back as a status or a warning for the caller (CLI, report) to
/// show. Bad input (mismatched lengths, a window outside the log, an all-missing output) throws
/// core::InputError instead.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dynpos/core/status.hpp"

namespace dynpos::ident {

/// Overall outcome of a fit: the library's one status convention (core/status.hpp).
using FitStatus = core::Status;

/// What a warning is about; the message gives the numbers.
enum class WarningCode {
  kSteadyStateNotReached,  ///< the end of the window still drifts relative to the noise
  kShortWindow,            ///< the window after the step is shorter than 3 time constants
  kPoorFit,                ///< R² below the threshold in the options
  kFewSamples,             ///< fewer samples after the step than the options ask for
  kDeadTimeAtBound,        ///< the dead time sits at 0 or at its upper limit
  kShapeOutOfRange,        ///< second order: the response is outside the overdamped range
  kNoSamplesForSign,       ///< thrust map: no samples for one sign of shaft speed
  kFewPreStepSamples,      ///< fewer than 3 samples to estimate the level before the step
};

/// Short stable identifier of a code, e.g. "steady_state_not_reached" (for JSON).
std::string_view warning_code_name(WarningCode code);

/// Short stable identifier of a status: "ok", "not_converged", "failed".
std::string_view fit_status_name(FitStatus status);

/// A warning raised by a fit: what it is and a human message with the numbers.
struct FitWarning {
  WarningCode code;
  std::string message;
};

/// An estimated value and, when the method gives one, its standard deviation (same unit).
struct Estimate {
  double value = 0.0;
  std::optional<double> sigma;  ///< 1σ from σ²(JᵀJ)⁻¹ at the optimum; absent for Smith-type
};

/// True when `warnings` holds a warning with this code.
bool has_warning(const std::vector<FitWarning>& warnings, WarningCode code);

}  // namespace dynpos::ident
