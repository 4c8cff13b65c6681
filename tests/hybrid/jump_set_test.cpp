#include "dynpos/hybrid/jump_set.hpp"

#include <gtest/gtest.h>

#include <string>

namespace dynpos::hybrid {
namespace {

TEST(JumpSet, Names) {
  EXPECT_EQ(std::string(to_string(JumpSet::kNone)), "none");
  EXPECT_EQ(std::string(to_string(JumpSet::kIdeal)), "ideal");
  EXPECT_EQ(std::string(to_string(JumpSet::kSampled)), "sampled");
}

}  // namespace
}  // namespace dynpos::hybrid
