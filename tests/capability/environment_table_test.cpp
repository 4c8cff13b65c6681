// The environment tables of capability/environment_table.hpp: DNV-ST-0111's Level 1 rows and
// the continuous environment between them.

#include "dynpos/capability/environment_table.hpp"

#include <gtest/gtest.h>

namespace dynpos::capability {
namespace {

TEST(EnvironmentTable, DnvNumbersAndTheContinuousEnvironment) {
  EXPECT_EQ(dp_number_for_wind(0.0), 0);
  EXPECT_EQ(dp_number_for_wind(10.7), 5);
  EXPECT_EQ(dp_number_for_wind(13.79), 5);
  EXPECT_EQ(dp_number_for_wind(40.0), 11);
  const Environment mid = dnv_level1_table().at(0.5 * (10.7 + 13.8));
  EXPECT_NEAR(mid.hs_m, 0.5 * (2.1 + 3.1), 1e-12);
  EXPECT_NEAR(mid.tp_s, 8.0, 1e-12);
  EXPECT_NEAR(mid.current_mps, 0.75, 1e-12);
}

}  // namespace
}  // namespace dynpos::capability
