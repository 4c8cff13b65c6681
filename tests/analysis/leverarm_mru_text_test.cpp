// The MRU files of leverarm mru given as NAME=FILE.

#include "dynpos/analysis/leverarm_mru_text.hpp"

#include <gtest/gtest.h>

#include "input_error_capture.hpp"

namespace dynpos::analysis {
namespace {

using testing::input_error;

TEST(LeverarmMruText, MruFilesByName) {
  const auto files = parse_mru_logs({"mru1=a.csv", "mru2=b.csv", "mru1=c.csv"});
  EXPECT_EQ(files,
            (std::map<std::string, std::filesystem::path>{{"mru1", "c.csv"}, {"mru2", "b.csv"}}));
  EXPECT_TRUE(parse_mru_logs({}).empty());
}

TEST(LeverarmMruText, AFileWithoutItsNameIsMalformed) {
  for (const char* spec : {"mru1", "mru1=", "=a.csv"}) {
    const core::InputError e = input_error([&] { parse_mru_logs({"mru2=b.csv", spec}); });
    EXPECT_EQ(e.option(), "mru_log");
    EXPECT_EQ(e.problem(), "malformed argument '" + std::string(spec) + "'");
    EXPECT_EQ(e.hint(), "expected NAME=FILE, e.g. --mru-log mru1=mru1.csv");
  }
}

}  // namespace
}  // namespace dynpos::analysis
