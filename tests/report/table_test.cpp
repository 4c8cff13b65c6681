#include "dynpos/report/table.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace dynpos::report {
namespace {

Table sample() {
  Table t;
  t.header = {"thruster", "thrust [kN]", "energy [kJ]"};
  t.rows = {{"port", "12.5", "3 400"}, {"tunnel", "—", "<1|2>"}};
  return t;
}

TEST(Table, TextAlignsNumbersRightCountingCodePoints) {
  // "—" is three bytes but one column wide.
  EXPECT_EQ(render_text(sample()),
            "thruster  thrust [kN]  energy [kJ]\n"
            "port             12.5        3 400\n"
            "tunnel              —        <1|2>\n");
}

// Finding H3: one 8 MiB cell padded every row of a compare table to 8 MiB (763 MB of output).
// A text cell is cut at kMaxTextCellWidth code points, on a character boundary.
TEST(Table, TextCellsAreCutSoOneLongCellDoesNotWidenEveryRow) {
  Table t;
  t.header = {"figure", "a"};
  std::string long_text;
  for (int i = 0; i < 1000; ++i) long_text += "é";  // two bytes, one column each
  t.rows = {{long_text, "1"}, {"x", "2"}};
  const std::string text = render_text(t);
  EXPECT_LT(text.size(), 3 * (2 * kMaxTextCellWidth + 8));
  const std::string cut = text.substr(text.find('\n') + 1, 2 * (kMaxTextCellWidth - 1));
  EXPECT_EQ(cut, long_text.substr(0, 2 * (kMaxTextCellWidth - 1)));
  EXPECT_NE(text.find(long_text.substr(0, 2 * (kMaxTextCellWidth - 1)) + "…  1\n"),
            std::string::npos);
  EXPECT_NE(text.find("\nx" + std::string(kMaxTextCellWidth - 1, ' ') + "  2\n"),
            std::string::npos);
}

TEST(Table, MarkdownEscapesPipesAndAlignsNumericColumns) {
  EXPECT_EQ(render_markdown(sample()),
            "| thruster | thrust [kN] | energy [kJ] |\n"
            "|---|---:|---:|\n"
            "| port | 12.5 | 3 400 |\n"
            "| tunnel | — | <1\\|2> |\n");
}

TEST(Table, HtmlEscapesMarkup) {
  const std::string html = render_html(sample());
  EXPECT_NE(html.find("<th>thrust [kN]</th>"), std::string::npos);
  EXPECT_NE(html.find("&lt;1|2&gt;"), std::string::npos);
  EXPECT_EQ(html.find("<1|2>"), std::string::npos);
}

TEST(Table, RaggedRowIsRejected) {
  Table t = sample();
  t.rows.push_back({"stb"});
  EXPECT_THROW(render_text(t), std::invalid_argument);
}

}  // namespace
}  // namespace dynpos::report
