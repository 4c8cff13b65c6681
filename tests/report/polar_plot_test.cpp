#include "dynpos/report/polar_plot.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace dynpos::report {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

PolarSeries series(std::string label, std::vector<double> r) {
  PolarSeries s;
  s.label = std::move(label);
  s.angle_deg = {0, 45, 90, 135, 180, -135, -90, -45};
  s.radius = std::move(r);
  return s;
}

PolarFigure agility_like() {
  PolarFigure f;
  f.title = "Agility & <test>";
  PolarPanel p;
  p.title = "50 % thrust";
  p.radial_label = "Response time";
  p.radial_unit = "s";
  p.series.push_back(series("port", {5, 6, 7, 8, 9, 8, 7, 6}));
  p.series.push_back(series("tunnel", {kNaN, 3, 3.5, 3, kNaN, 3, 3.5, 3}));
  p.arrows.push_back({"wind 3.3 m/s", 203.0, 0.6, "#2ca02c"});
  f.panels.push_back(p);
  return f;
}

// Every element opens and closes: a stack check of the tags (no attribute contains '<' or
// '>', since text is escaped).
bool balanced(const std::string& svg) {
  std::vector<std::string> stack;
  std::size_t pos = 0;
  while ((pos = svg.find('<', pos)) != std::string::npos) {
    const std::size_t end = svg.find('>', pos);
    if (end == std::string::npos) return false;
    const std::string tag = svg.substr(pos + 1, end - pos - 1);
    pos = end + 1;
    if (tag.empty()) return false;
    if (tag.back() == '/') continue;  // self-closing
    const std::string name =
        tag.substr(tag[0] == '/' ? 1 : 0, tag.find_first_of(" \n") - (tag[0] == '/' ? 1 : 0));
    if (tag[0] == '/') {
      if (stack.empty() || stack.back() != name) return false;
      stack.pop_back();
    } else {
      stack.push_back(name);
    }
  }
  return stack.empty();
}

// The text between `open` and the next `close` after position `from`, or npos when absent.
std::string between(const std::string& s, std::size_t& from, const std::string& open,
                    const std::string& close) {
  const std::size_t a = s.find(open, from);
  if (a == std::string::npos) {
    from = std::string::npos;
    return {};
  }
  const std::size_t b = s.find(close, a + open.size());
  from = b;
  return s.substr(a + open.size(), b - a - open.size());
}

std::vector<std::pair<double, double>> markers(const std::string& svg) {
  std::vector<std::pair<double, double>> out;
  const std::string tag = "class=\"marker\" cx=\"";
  for (std::size_t at = svg.find(tag); at != std::string::npos; at = svg.find(tag, at + 1)) {
    std::size_t from = at;
    const std::string cx = between(svg, from, "cx=\"", "\"");
    const std::string cy = between(svg, from, "cy=\"", "\"");
    out.emplace_back(std::stod(cx), std::stod(cy));
  }
  return out;
}

TEST(PolarPlot, IsWellFormedAndDeterministic) {
  const std::string svg = render_polar_svg(agility_like());
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  EXPECT_TRUE(balanced(svg));
  EXPECT_THAT(svg, ::testing::HasSubstr("Agility &amp; &lt;test&gt;"));
  EXPECT_EQ(svg, render_polar_svg(agility_like()));
}

TEST(PolarPlot, RingsAreLabelledAndAnglesRunClockwiseFromTheTop) {
  const PolarFigure f = agility_like();
  const std::string svg = render_polar_svg(f);
  const PolarLayout l = polar_layout(f, 0);
  // Data up to 9 s: nice rings every 2 s up to 10 s.
  EXPECT_DOUBLE_EQ(l.r_max, 10.0);
  EXPECT_THAT(l.rings, ::testing::ElementsAre(2.0, 4.0, 6.0, 8.0, 10.0));
  for (const char* label : {">2<", ">4<", ">6<", ">8<", ">10<"}) {
    EXPECT_THAT(svg, ::testing::HasSubstr(std::string("class=\"ring-label\"") + label));
  }
  for (const char* label : {">0°<", ">45°<", ">90°<", ">180°<", ">−90°<", ">−45°<"}) {
    EXPECT_THAT(svg, ::testing::HasSubstr(label));
  }
  EXPECT_THAT(svg, ::testing::HasSubstr("radius: Response time [s]"));
}

TEST(PolarPlot, ARingStepGivesOneRingPerStep) {
  PolarFigure f = agility_like();
  f.panels[0].r_max = 11.0;
  f.panels[0].ring_step = 1.0;
  const PolarLayout l = polar_layout(f, 0);
  EXPECT_DOUBLE_EQ(l.r_max, 11.0);
  EXPECT_THAT(l.rings, ::testing::ElementsAre(1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11));
  EXPECT_THAT(render_polar_svg(f), ::testing::HasSubstr("class=\"ring-label\">11<"));
  f.panels[0].r_max.reset();
  EXPECT_THROW(f.validate(), std::invalid_argument);  // a ring step needs the outer ring
  f.panels[0].r_max = 11.0;
  f.panels[0].ring_step = 0.01;
  EXPECT_THROW(f.validate(), std::invalid_argument);  // more than 100 rings
}

TEST(PolarPlot, APointLandsWhereTrigonometrySays) {
  const PolarFigure f = agility_like();
  const PolarLayout l = polar_layout(f, 0);
  const auto m = markers(render_polar_svg(f));
  // 8 port points and 6 present tunnel points (the two NaN are gaps, not the centre).
  ASSERT_EQ(m.size(), 14u);
  const auto& s = f.panels[0].series[0];
  for (std::size_t i = 0; i < s.radius.size(); ++i) {
    const double th = s.angle_deg[i] * std::numbers::pi / 180.0;
    // Coordinates are written with 2 decimals: within 0.005 px.
    EXPECT_NEAR(m[i].first, l.cx + s.radius[i] * l.scale * std::sin(th), 0.006) << i;
    EXPECT_NEAR(m[i].second, l.cy - s.radius[i] * l.scale * std::cos(th), 0.006) << i;
  }
  // 0° (ahead) is straight up, 90° straight right: compass-like.
  EXPECT_NEAR(m[0].first, l.cx, 0.006);
  EXPECT_LT(m[0].second, l.cy);
  EXPECT_GT(m[2].first, l.cx);
  EXPECT_NEAR(m[2].second, l.cy, 0.006);
  for (const auto& [x, y] : m) EXPECT_FALSE(x == l.cx && y == l.cy);
}

TEST(PolarPlot, GapsSplitTheLineAndClosedSeriesWrap) {
  const std::string svg = render_polar_svg(agility_like());
  // Port is closed: one polyline of 9 points (first repeated). Tunnel: two runs of 3 points.
  std::vector<std::size_t> sizes;
  for (std::size_t at = svg.find("<polyline"); at != std::string::npos;
       at = svg.find("<polyline", at + 1)) {
    std::size_t from = at;
    const std::string pts = between(svg, from, "points=\"", "\"");
    sizes.push_back(static_cast<std::size_t>(std::count(pts.begin(), pts.end(), ' ')) + 1);
  }
  EXPECT_THAT(sizes, ::testing::ElementsAre(9u, 3u, 3u));
}

TEST(PolarPlot, FixedRangeClampsToTheRimAndArrowsAreDrawn) {
  PolarFigure f = agility_like();
  f.panels[0].r_max = 5.0;
  const PolarLayout l = polar_layout(f, 0);
  EXPECT_DOUBLE_EQ(l.r_max, 5.0);
  const auto m = markers(render_polar_svg(f));
  // 9 s at 180° is drawn on the 5 s rim.
  EXPECT_NEAR(m[4].second, l.cy + 5.0 * l.scale, 0.006);
  const std::string svg = render_polar_svg(f);
  EXPECT_THAT(svg, ::testing::HasSubstr("class=\"arrow\""));
  EXPECT_THAT(svg, ::testing::HasSubstr(">wind 3.3 m/s<"));
}

TEST(PolarPlot, PanelsSitSideBySide) {
  PolarFigure f = agility_like();
  f.panels.push_back(f.panels[0]);
  const PolarLayout a = polar_layout(f, 0);
  const PolarLayout b = polar_layout(f, 1);
  EXPECT_GT(b.cx, a.cx + f.panel_size_px);
  EXPECT_DOUBLE_EQ(a.cy, b.cy);
  EXPECT_THROW(polar_layout(f, 2), std::out_of_range);
}

TEST(PolarPlot, InvalidFiguresAreRejected) {
  PolarFigure f = agility_like();
  f.panels[0].series[0].radius.pop_back();
  EXPECT_THROW(render_polar_svg(f), std::invalid_argument);
  f = agility_like();
  f.panels[0].r_max = 0.0;
  EXPECT_THROW(render_polar_svg(f), std::invalid_argument);
  f = agility_like();
  f.panels[0].arrows[0].length = 1.5;
  EXPECT_THROW(render_polar_svg(f), std::invalid_argument);
  EXPECT_THROW(render_polar_svg(PolarFigure{}), std::invalid_argument);
}

TEST(PolarPlot, WritesTheFile) {
  const auto path = std::filesystem::temp_directory_path() / "dynpos_polar_plot_test.svg";
  write_polar_svg(path, agility_like());
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), render_polar_svg(agility_like()));
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace dynpos::report
