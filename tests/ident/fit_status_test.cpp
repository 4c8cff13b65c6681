#include "dynpos/ident/fit_status.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace dynpos::ident {
namespace {

TEST(FitStatus, NamesAreStableAndDistinct) {
  EXPECT_EQ(fit_status_name(FitStatus::kOk), "ok");
  EXPECT_EQ(fit_status_name(FitStatus::kNotConverged), "not_converged");
  EXPECT_EQ(fit_status_name(FitStatus::kFailed), "failed");
  const WarningCode codes[] = {WarningCode::kSteadyStateNotReached,
                               WarningCode::kShortWindow,
                               WarningCode::kPoorFit,
                               WarningCode::kFewSamples,
                               WarningCode::kDeadTimeAtBound,
                               WarningCode::kShapeOutOfRange,
                               WarningCode::kNoSamplesForSign,
                               WarningCode::kFewPreStepSamples};
  std::set<std::string> names;
  for (WarningCode c : codes) names.insert(std::string(warning_code_name(c)));
  EXPECT_EQ(names.size(), std::size(codes));
  EXPECT_EQ(warning_code_name(WarningCode::kSteadyStateNotReached), "steady_state_not_reached");
}

TEST(FitStatus, HasWarning) {
  const std::vector<FitWarning> w{{WarningCode::kPoorFit, "R² = 0.5"}};
  EXPECT_TRUE(has_warning(w, WarningCode::kPoorFit));
  EXPECT_FALSE(has_warning(w, WarningCode::kShortWindow));
  EXPECT_FALSE(has_warning({}, WarningCode::kPoorFit));
}

}  // namespace
}  // namespace dynpos::ident
