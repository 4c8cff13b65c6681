// capability --loads takes the vessel, the failure and the JSON only: an option of the roses
// given with it is named.

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <string_view>

#include "dynpos/analysis/feasibility.hpp"
#include "dynpos/analysis/option_spelling.hpp"
#include "input_error_capture.hpp"

namespace dynpos::analysis {
namespace {

using testing::input_error;

TEST(LoadsOptions, TheLoadTablesOwnOptionsPass) {
  const std::set<std::string, std::less<>> given = {"vessel", "failure", "json", "loads"};
  EXPECT_NO_THROW(check_loads_options([&](std::string_view name) { return given.contains(name); }));
}

TEST(LoadsOptions, AnOptionOfTheRosesIsNamed) {
  for (const char* option : {"level", "direction-step", "seed", "out", "transient", "observer"}) {
    const core::InputError e = input_error(
        [&] { check_loads_options([&](std::string_view name) { return name == option; }); });
    EXPECT_EQ(e.option(), "loads");
    EXPECT_EQ(cli_message(e), "(--loads): --" + std::string(option) +
                                  " is not an option of the load table's factors; with --loads "
                                  "give --vessel, --failure and --json only");
  }
}

TEST(LoadsOptions, TheFirstInTheHelpsOrderIsNamed) {
  const core::InputError e = input_error([] {
    check_loads_options([](std::string_view name) { return name == "jobs" || name == "hs"; });
  });
  EXPECT_EQ(e.problem(), "--hs is not an option of the load table's factors");
}

}  // namespace
}  // namespace dynpos::analysis
