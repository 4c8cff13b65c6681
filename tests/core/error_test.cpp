#include "dynpos/core/error.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <string_view>

#include "dynpos/core/printable_text.hpp"

namespace dynpos::core {
namespace {

using ::testing::MatchesRegex;

TEST(InputError, FullLocationFormat) {
  const InputError e({"trial/aug.csv", 12, 3, "heading"}, "'abc' is not a number",
                     "write heading in degrees");
  EXPECT_THAT(e.what(), MatchesRegex(R"(trial/aug\.csv:12:3 \(heading\): 'abc' is not a number; )"
                                     R"(write heading in degrees)"));
  // The general shape every CLI message follows: file:line:column (name): problem; hint.
  EXPECT_THAT(e.what(), MatchesRegex(R"([^:]+:[0-9]+:[0-9]+ \([^)]+\): [^;]+; .+)"));
}

TEST(InputError, PartialLocations) {
  EXPECT_THAT(format_input_error({"map.toml", {}, {}, ""}, "unknown role 'nrth'", ""),
              MatchesRegex(R"(map\.toml: unknown role 'nrth')"));
  EXPECT_THAT(format_input_error({"map.toml", 7, {}, ""}, "bad unit", "use deg or rad"),
              MatchesRegex(R"(map\.toml:7: bad unit; use deg or rad)"));
  EXPECT_THAT(format_input_error({"", 5, 2, "u"}, "empty field", ""),
              MatchesRegex(R"(line 5, column 2 \(u\): empty field)"));
  EXPECT_THAT(format_input_error({"", 5, {}, ""}, "empty field", ""),
              MatchesRegex(R"(line 5: empty field)"));
  EXPECT_THAT(format_input_error({"", {}, {}, "roll"}, "channel missing", "map the role"),
              MatchesRegex(R"(\(roll\): channel missing; map the role)"));
  EXPECT_THAT(format_input_error({}, "no input", ""), MatchesRegex("no input"));
}

TEST(InputError, NoHintMeansNoSeparator) {
  const std::string text = format_input_error({"a.csv", 1, 1, "t"}, "time not increasing", "");
  EXPECT_THAT(text, MatchesRegex(R"(a\.csv:1:1 \(t\): time not increasing)"));
  EXPECT_EQ(text.find(';'), std::string::npos);
}

TEST(InputError, KeepsItsParts) {
  try {
    throw InputError({"log.csv", 40, 6, "n_port"}, "value out of range", "check the unit");
  } catch (const std::runtime_error& caught) {  // the CLI catches it as a runtime_error
    const auto* e = dynamic_cast<const InputError*>(&caught);
    ASSERT_NE(e, nullptr);
    EXPECT_EQ(e->where().file, "log.csv");
    EXPECT_EQ(e->where().line, 40u);
    EXPECT_EQ(e->where().column, 6u);
    EXPECT_EQ(e->where().column_name, "n_port");
    EXPECT_EQ(e->problem(), "value out of range");
    EXPECT_EQ(e->hint(), "check the unit");
    EXPECT_EQ(std::string(e->what()), format_input_error(e->where(), e->problem(), e->hint()));
  }
}

TEST(InputError, AnOptionErrorCanNameTheFileItWasCheckedAgainst) {
  const InputError plain = InputError::for_option("from/to", "outside the log", "choose");
  EXPECT_EQ(plain.option(), "from/to");
  EXPECT_EQ(plain.where().file, "");
  EXPECT_EQ(std::string(plain.what()), "(from/to): outside the log; choose");
  const InputError in_file = InputError::for_option("from/to", "outside the log", "", "a.csv");
  EXPECT_EQ(in_file.option(), "from/to");
  EXPECT_EQ(in_file.where().file, "a.csv");
  EXPECT_EQ(std::string(in_file.what()), "a.csv (from/to): outside the log");
}

}  // namespace
}  // namespace dynpos::core

namespace dynpos::core {
namespace {

TEST(InputErrorText, ControlCharactersAreShownNotSent) {
  const InputError e({"log.csv", 3, 2, "speed"}, "'\x1b[31mred\x1b[0m' is not a number",
                     "tab\there");
  EXPECT_STREQ(e.what(), "log.csv:3:2 (speed): '\\x1b[31mred\\x1b[0m' is not a number; tab\\there");
  EXPECT_EQ(e.problem(), "'\x1b[31mred\x1b[0m' is not a number");  // the text itself is kept
}

TEST(InputErrorText, C1ControlsAndInvalidUtf8AreShownNotSent) {
  // U+009B (CSI, "\xc2\x9b") starts an escape sequence on many terminals, as ESC [ does.
  EXPECT_EQ(printable("a\xc2\x9b"
                      "31mb"),
            "a\\u009b31mb");
  EXPECT_EQ(printable("\xc2\x80\xc2\x9f\xc2\xa0"), "\\u0080\\u009f\xc2\xa0");  // NBSP stays
  // A lone 0x9b byte (CSI in 8-bit terminals), a stray continuation byte, a truncated and an
  // overlong sequence, a surrogate: each invalid byte as \xNN, the valid text around it kept.
  EXPECT_EQ(printable("x\x9by"), "x\\x9by");
  EXPECT_EQ(printable("\xe2\x82"), "\\xe2\\x82");
  EXPECT_EQ(printable("\xc0\xaf"), "\\xc0\\xaf");
  EXPECT_EQ(printable("\xed\xa0\x80"), "\\xed\\xa0\\x80");
  EXPECT_EQ(printable("\xff"), "\\xff");
  EXPECT_EQ(printable("é€😀—"), "é€😀—");  // 2-, 3- and 4-byte characters pass
  const InputError e({"log\x9b.csv", 1, {}, {}}, "cell '\xc2\x9b'");
  EXPECT_STREQ(e.what(), "log\\x9b.csv:1: cell '\\u009b'");
}

TEST(InputErrorText, TextKeepsLineEndsAndTabs) {
  EXPECT_EQ(printable_text("a\tb\nc\x1b[0m\xc2\x9b\xff"), "a\tb\nc\\x1b[0m\\u009b\\xff");
}

TEST(InputErrorText, ALongEchoIsCutAtACharacter) {
  const std::string huge(1'000'000, 'x');
  const InputError e({"log.csv", 1, {}, {}}, "header '" + huge + "'");
  const std::string what = e.what();
  EXPECT_LT(what.size(), 1100u);
  EXPECT_NE(what.find("… (999"), std::string::npos);
  // A cut inside a multi-byte character backs off to its start: "é" is 2 bytes.
  std::string text;
  for (int i = 0; i < 600; ++i) text += "é";
  const std::string spaced = " " + text;            // 1201 bytes
  const std::string cut = printable(spaced, 1000);  // the 1000th byte is inside an "é"
  EXPECT_EQ(cut.compare(0, 999, spaced, 0, 999), 0);
  EXPECT_EQ(cut.compare(999, std::string_view("… (").size(), "… ("), 0);
}

}  // namespace
}  // namespace dynpos::core
