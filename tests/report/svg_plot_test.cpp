#include "dynpos/report/svg_plot.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace dynpos::report {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A small well-formedness check: every tag closes in order, attributes are quoted, and text
// holds no raw '<' and no '&' that does not start an entity. Returns "" or the first problem.
std::string xml_problem(const std::string& doc) {
  std::vector<std::string> stack;
  std::size_t i = 0;
  if (doc.rfind("<?xml", 0) == 0) i = doc.find("?>") + 2;
  // std::regex is avoided on purpose: GCC 12 warns inside it under the sanitizers.
  const auto is_entity = [&doc](std::size_t at) {
    for (const char* e : {"&amp;", "&lt;", "&gt;", "&quot;", "&apos;"}) {
      if (doc.compare(at, std::char_traits<char>::length(e), e) == 0) return true;
    }
    return false;
  };
  while (i < doc.size()) {
    if (doc[i] == '&') {
      if (!is_entity(i)) return "bare & at " + std::to_string(i);
      ++i;
      continue;
    }
    if (doc[i] != '<') {
      if (doc[i] == '>') return "bare > at " + std::to_string(i);
      ++i;
      continue;
    }
    // Find the end of the tag, skipping quoted attribute values.
    std::size_t j = i + 1;
    char quote = 0;
    for (; j < doc.size(); ++j) {
      if (quote) {
        if (doc[j] == quote)
          quote = 0;
        else if (doc[j] == '<')
          return "'<' inside an attribute at " + std::to_string(j);
      } else if (doc[j] == '"' || doc[j] == '\'') {
        quote = doc[j];
      } else if (doc[j] == '>') {
        break;
      }
    }
    if (j == doc.size()) return "unterminated tag at " + std::to_string(i);
    const std::string tag = doc.substr(i + 1, j - i - 1);
    if (tag.empty()) return "empty tag";
    if (tag[0] == '/') {
      const std::string name = tag.substr(1);
      if (stack.empty() || stack.back() != name) return "unexpected </" + name + ">";
      stack.pop_back();
    } else if (tag.back() != '/') {
      stack.push_back(tag.substr(0, tag.find_first_of(" \n\t")));
    }
    i = j + 1;
  }
  if (!stack.empty()) return "unclosed <" + stack.back() + ">";
  return "";
}

Figure two_panel_figure() {
  Figure f;
  f.title = "States <x₁> & \"x₂\"";
  Panel p;
  p.title = "Position error";
  p.x_axis = {"Time", "s", {}, {}};
  p.y_axis = {"x₁", "m", {}, {}};
  Series a{"hybrid", {0, 1, 2, 3}, {0.0, 1.0, 0.5, 0.25}, "", 1.5, false};
  Series b{"conventional", {0, 1, 2, 3}, {0.0, 2.0, 1.5, 1.0}, "", 1.5, true};
  p.series = {a, b};
  p.x_markers = {1.5};
  f.panels.push_back(p);
  p.title = "Second";
  p.zoom = XRange{0.5, 1.5};
  f.panels.push_back(p);
  return f;
}

// The d attributes of the series paths, in order.
std::vector<std::string> path_data(const std::string& svg) {
  std::vector<std::string> out;
  for (std::size_t at = svg.find("class=\"series\""); at != std::string::npos;
       at = svg.find("class=\"series\"", at + 1)) {
    const std::size_t end_of_tag = svg.find("/>", at);
    const std::size_t d = svg.find(" d=\"", at);
    if (d == std::string::npos || d > end_of_tag) continue;
    const std::size_t close = svg.find('"', d + 4);
    out.push_back(svg.substr(d + 4, close - d - 4));
  }
  return out;
}

// The y coordinates of the points "x,y" of a path's d attribute.
std::vector<double> path_ys(const std::string& d) {
  std::vector<double> ys;
  std::istringstream words(d);
  std::string word;
  while (words >> word) {
    const std::size_t comma = word.find(',');
    if (comma == std::string::npos || word == "l0,0") continue;
    ys.push_back(std::stod(word.substr(comma + 1)));
  }
  return ys;
}

TEST(SvgPlot, IsWellFormedAndEscapesText) {
  const std::string svg = render_svg(two_panel_figure());
  EXPECT_EQ(xml_problem(svg), "");
  EXPECT_THAT(svg, HasSubstr("<svg xmlns=\"http://www.w3.org/2000/svg\""));
  EXPECT_THAT(svg, HasSubstr("States &lt;x₁&gt; &amp; &quot;x₂&quot;"));
  EXPECT_THAT(svg, Not(HasSubstr("<x₁>")));
}

TEST(SvgPlot, TheCheckerCatchesBrokenDocuments) {
  // The checker itself must be able to fail, or the test above proves nothing.
  EXPECT_NE(xml_problem("<svg><g></svg>"), "");
  EXPECT_NE(xml_problem("<svg>a & b</svg>"), "");
  EXPECT_NE(xml_problem("<svg><text>1 < 2</text></svg>"), "");
  EXPECT_EQ(xml_problem("<svg><g a=\"x&amp;y\"/></svg>"), "");
}

TEST(SvgPlot, HasLabelsUnitsLegendTicksAndMarkers) {
  const std::string svg = render_svg(two_panel_figure());
  EXPECT_THAT(svg, HasSubstr(">Time [s]</text>"));
  EXPECT_THAT(svg, HasSubstr(">x₁ [m]</text>"));
  EXPECT_THAT(svg, HasSubstr("class=\"legend\""));
  EXPECT_THAT(svg, HasSubstr(">hybrid</text>"));
  EXPECT_THAT(svg, HasSubstr(">conventional</text>"));
  EXPECT_THAT(svg, HasSubstr("class=\"marker\""));
  EXPECT_THAT(svg, HasSubstr("stroke-dasharray=\"6,4\""));  // the dashed series
  // x ticks 0, 0.5, …, 3 (nice step for a 0–3 s axis with ~10 intervals is 0.5).
  EXPECT_THAT(svg, HasSubstr(">2.5</text>"));
  // Two panels + one zoom subplot, each with its own clip path.
  EXPECT_EQ(path_data(svg).size(), 6u);
  EXPECT_THAT(svg, HasSubstr("id=\"clip3\""));
  EXPECT_THAT(svg, HasSubstr("zoom on 0.50 … 1.50 s"));
  EXPECT_THAT(svg, HasSubstr("class=\"zoom-band\""));
}

TEST(SvgPlot, NanGapsBreakTheLineInsteadOfDrawingToZero) {
  Figure f;
  Panel p;
  p.x_axis = {"t", "s", 0.0, 4.0};
  p.y_axis = {"y", "", 0.0, 10.0};
  // y = 5 everywhere except a missing sample at t = 2.
  p.series = {Series{"s", {0, 1, 2, 3, 4}, {5, 5, kNaN, 5, 5}, "#000000", 1.0, false}};
  f.panels.push_back(p);
  const std::vector<std::string> paths = path_data(render_svg(f));
  ASSERT_EQ(paths.size(), 1u);
  // Two sub-paths, each starting with M; no point of the line is at y = 0 (the bottom edge).
  EXPECT_EQ(std::count(paths[0].begin(), paths[0].end(), 'M'), 2);
  const std::vector<double> ys = path_ys(paths[0]);
  ASSERT_EQ(ys.size(), 4u);  // the NaN is not a point
  for (const double y : ys) EXPECT_DOUBLE_EQ(y, ys.front());
}

TEST(SvgPlot, LonePointBetweenGapsIsADot) {
  Figure f;
  Panel p;
  p.series = {Series{"", {0, 1, 2}, {kNaN, 1.0, kNaN}, "", 1.0, false}};
  f.panels.push_back(p);
  const std::vector<std::string> paths = path_data(render_svg(f));
  ASSERT_EQ(paths.size(), 1u);
  EXPECT_THAT(paths[0], HasSubstr("l0,0"));
}

TEST(SvgPlot, LongSeriesAreDecimatedButKeepPeaks) {
  Figure f;
  Panel p;
  Series s;
  s.label = "long";
  for (int i = 0; i < 200000; ++i) {
    s.x.push_back(i * 1e-3);
    s.y.push_back(i == 123456 ? 100.0 : std::sin(i * 1e-3));
  }
  p.series = {s};
  f.panels.push_back(p);
  const std::string svg = render_svg(f);
  EXPECT_EQ(xml_problem(svg), "");
  // 800 columns × ≤ 4 points × ~16 bytes per point: well under 100 kB (the raw data would be
  // 200000 points × 16 bytes ≈ 3 MB).
  EXPECT_LT(svg.size(), 100000u);
  // The y axis reaches the spike (ticks up to 100), so the spike is in range and drawn.
  EXPECT_THAT(svg, HasSubstr(">100</text>"));
}

TEST(SvgPlot, FixedRangesAndAutoRangesWithAllMissingData) {
  Figure f;
  Panel p;
  p.y_axis = {"y", "", {}, {}};
  p.series = {Series{"missing", {0, 1}, {kNaN, kNaN}, "", 1.0, false}};
  f.panels.push_back(p);
  const std::string svg = render_svg(f);
  EXPECT_EQ(xml_problem(svg), "");
  EXPECT_TRUE(path_data(svg).empty());  // nothing to draw, and no made-up zeros
}

TEST(SvgPlot, DeterministicBytes) {
  EXPECT_EQ(render_svg(two_panel_figure()), render_svg(two_panel_figure()));
}

TEST(SvgPlot, RejectsInvalidFigures) {
  Figure f = two_panel_figure();
  f.panels[0].series[0].y.pop_back();
  EXPECT_THROW(
      {
        try {
          render_svg(f);
        } catch (const std::invalid_argument& e) {
          EXPECT_THAT(e.what(), HasSubstr("4 x values but 3 y values"));
          throw;
        }
      },
      std::invalid_argument);
  f = two_panel_figure();
  f.panels[1].zoom = XRange{2.0, 1.0};
  EXPECT_THROW(render_svg(f), std::invalid_argument);
  f = two_panel_figure();
  f.panels[0].y_axis.min = 3.0;
  f.panels[0].y_axis.max = 3.0;
  EXPECT_THROW(render_svg(f), std::invalid_argument);
  f = two_panel_figure();
  f.width_px = 10.0;
  EXPECT_THROW(render_svg(f), std::invalid_argument);
}

TEST(SvgPlot, WriteSvgIsAtomic) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("dynpos_svg_test_" + std::to_string(std::random_device{}()));
  std::filesystem::create_directories(dir);
  const std::filesystem::path target = dir / "plot.svg";
  write_svg(target, two_panel_figure());
  std::ifstream in(target);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), render_svg(two_panel_figure()));
  // An invalid figure throws before anything is created, and leaves the old file alone.
  Figure bad = two_panel_figure();
  bad.width_px = 0.0;
  EXPECT_THROW(write_svg(target, bad), std::invalid_argument);
  int files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1);
  // A folder that does not exist is a runtime error naming the path.
  EXPECT_THROW(write_svg(dir / "no" / "such" / "plot.svg", two_panel_figure()), std::runtime_error);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace dynpos::report
