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
