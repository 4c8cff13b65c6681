#include "dynpos/io/markup.hpp"

#include <gtest/gtest.h>

namespace dynpos::io {
namespace {

TEST(Markup, EscapesTheFiveMarkupCharacters) {
  EXPECT_EQ(escape_markup(R"(<a href="x">Tom & Jerry's</a>)"),
            "&lt;a href=&quot;x&quot;&gt;Tom &amp; Jerry&apos;s&lt;/a&gt;");
}

TEST(Markup, LeavesOtherTextAloneIncludingUtf8) {
  EXPECT_EQ(escape_markup(""), "");
  EXPECT_EQ(escape_markup("Δy = 3 m/s² at 63.2 %"), "Δy = 3 m/s² at 63.2 %");
  // An entity already written is escaped again: the function does not guess intent.
  EXPECT_EQ(escape_markup("&amp;"), "&amp;amp;");
}

}  // namespace
}  // namespace dynpos::io
