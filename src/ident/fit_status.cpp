#include "dynpos/ident/fit_status.hpp"

#include <algorithm>

namespace dynpos::ident {

std::string_view warning_code_name(WarningCode code) {
  switch (code) {
    case WarningCode::kSteadyStateNotReached:
      return "steady_state_not_reached";
    case WarningCode::kShortWindow:
      return "short_window";
    case WarningCode::kPoorFit:
      return "poor_fit";
    case WarningCode::kFewSamples:
      return "few_samples";
    case WarningCode::kDeadTimeAtBound:
      return "dead_time_at_bound";
    case WarningCode::kShapeOutOfRange:
      return "shape_out_of_range";
    case WarningCode::kNoSamplesForSign:
      return "no_samples_for_sign";
    case WarningCode::kFewPreStepSamples:
      return "few_pre_step_samples";
  }
  return "unknown";
}

std::string_view fit_status_name(FitStatus status) { return core::status_name(status); }

bool has_warning(const std::vector<FitWarning>& warnings, WarningCode code) {
  return std::any_of(warnings.begin(), warnings.end(),
                     [code](const FitWarning& w) { return w.code == code; });
}

}  // namespace dynpos::ident
