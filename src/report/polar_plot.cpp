#include "dynpos/report/polar_plot.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "dynpos/io/atomic_file.hpp"
#include "dynpos/io/markup.hpp"
#include "dynpos/report/axis_ticks.hpp"

namespace dynpos::report {
namespace {

// Layout [px]: a figure title, then the panels side by side. Each panel block has a title
// line, a radial-axis line, padding for the angle labels around the circle, the circle, and a
// legend below it.
constexpr double kFigureTitleHeight = 34.0;
constexpr double kPanelTitleHeight = 22.0;
constexpr double kAxisLabelHeight = 18.0;
constexpr double kPad = 40.0;
constexpr double kLegendRow = 18.0;
constexpr double kFontSize = 12.0;
constexpr double kMarkerRadius = 3.0;
constexpr double kMaxPixel = 1.0e6;

constexpr std::array<const char*, 8> kPalette = {"#1f77b4", "#d62728", "#ff7f0e", "#9467bd",
                                                 "#8c564b", "#e377c2", "#7f7f7f", "#17becf"};

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("PolarFigure: " + what);
}

std::string px(double v) { return fmt::format("{:.2f}", std::clamp(v, -kMaxPixel, kMaxPixel)); }

double rad(double deg) { return deg * std::numbers::pi / 180.0; }

std::size_t legend_rows(const PolarPanel& p) {
  if (!p.legend) return 0;
  return static_cast<std::size_t>(std::count_if(
      p.series.begin(), p.series.end(), [](const PolarSeries& s) { return !s.label.empty(); }));
}

double block_width(const PolarFigure& f) { return f.panel_size_px + 2.0 * kPad + 40.0; }

double block_height(const PolarFigure& f) {
  std::size_t rows = 0;
  for (const PolarPanel& p : f.panels) rows = std::max(rows, legend_rows(p));
  return kPanelTitleHeight + kAxisLabelHeight + 2.0 * kPad + f.panel_size_px +
         static_cast<double>(rows) * kLegendRow + 10.0;
}

// The radial extent: fixed, or the largest finite radius widened to a nice tick.
AxisTicks radial_ticks(const PolarPanel& p) {
  if (p.r_max && p.ring_step) {
    AxisTicks t{0.0, *p.r_max, *p.ring_step, {}, *p.ring_step >= 1.0 ? 0 : 1};
    for (int k = 0; k * *p.ring_step <= *p.r_max * (1.0 + 1e-12); ++k) {
      t.values.push_back(k * *p.ring_step);
    }
    return t;
  }
  if (p.r_max) return nice_ticks(0.0, *p.r_max, 5, false);
  double hi = 0.0;
  for (const PolarSeries& s : p.series) {
    const std::size_t n = std::min(s.angle_deg.size(), s.radius.size());
    for (std::size_t i = 0; i < n; ++i) {
      if (std::isfinite(s.radius[i]) && std::isfinite(s.angle_deg[i])) {
        hi = std::max(hi, std::abs(s.radius[i]));
      }
    }
  }
  if (!(hi > 0.0)) hi = 1.0;
  return nice_ticks(0.0, hi, 5, true);
}

// A compass angle label in (−180, 180], e.g. "−135°".
std::string angle_text(double deg) {
  double w = std::fmod(deg, 360.0);
  if (w > 180.0) w -= 360.0;
  if (w <= -180.0) w += 360.0;
  const std::string number = format_tick(w, std::abs(w - std::round(w)) < 1e-9 ? 0 : 1);
  return number + "°";
}

struct Point {
  double x;
  double y;
};

Point to_px(const PolarLayout& l, double angle_deg, double r) {
  const double rr = std::min(std::max(r, 0.0), l.r_max);  // beyond the rim: on the rim
  return {l.cx + rr * l.scale * std::sin(rad(angle_deg)),
          l.cy - rr * l.scale * std::cos(rad(angle_deg))};
}

std::string points_attr(const std::vector<Point>& pts) {
  std::string s;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (i > 0) s += ' ';
    s += px(pts[i].x) + "," + px(pts[i].y);
  }
  return s;
}

// The panel's title and radial-axis line above the circle.
void render_titles(std::string& out, const PolarPanel& p, const PolarLayout& l) {
  const double y_title = kFigureTitleHeight + kPanelTitleHeight - 6.0;
  if (!p.title.empty()) {
    out += fmt::format(
        "<text x=\"{}\" y=\"{}\" text-anchor=\"middle\" font-weight=\"bold\">{}</text>\n", px(l.cx),
        px(y_title), io::escape_markup(p.title));
  }
  const std::string axis =
      p.radial_unit.empty() ? p.radial_label : p.radial_label + " [" + p.radial_unit + "]";
  if (!axis.empty()) {
    out += fmt::format(
        "<text x=\"{}\" y=\"{}\" text-anchor=\"middle\" fill=\"#444\">radius: {}</text>\n",
        px(l.cx), px(y_title + kAxisLabelHeight), io::escape_markup(axis));
  }
}

// Rings with labels along the 0° spoke, then the spokes with angle labels.
void render_grid(std::string& out, const PolarPanel& p, const PolarLayout& l) {
  const double R = l.r_max * l.scale;
  const AxisTicks ticks = radial_ticks(p);
  out += "<g class=\"grid\" fill=\"none\" stroke=\"#ccc\">\n";
  for (const double r : l.rings) {
    out += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"{}\"/>\n", px(l.cx), px(l.cy),
                       px(r * l.scale));
  }
  const int n_spokes = static_cast<int>(std::floor(360.0 / p.angle_step_deg + 1e-9));
  for (int k = 0; k < n_spokes; ++k) {
    const Point e = to_px(l, k * p.angle_step_deg, l.r_max);
    out += fmt::format("<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\"/>\n", px(l.cx), px(l.cy),
                       px(e.x), px(e.y));
  }
  out += "</g>\n<g class=\"ring-labels\" fill=\"#555\">\n";
  for (const double r : l.rings) {
    out += fmt::format("<text x=\"{}\" y=\"{}\" class=\"ring-label\">{}</text>\n", px(l.cx + 3.0),
                       px(l.cy - r * l.scale - 3.0),
                       io::escape_markup(format_tick(r, ticks.decimals)));
  }
  out += "</g>\n<g class=\"angle-labels\" text-anchor=\"middle\">\n";
  for (int k = 0; k < n_spokes; ++k) {
    const double a = k * p.angle_step_deg;
    const double d = R + 16.0;
    const double x = l.cx + d * std::sin(rad(a));
    const double y = l.cy - d * std::cos(rad(a)) + kFontSize / 3.0;
    const std::string name =
        static_cast<std::size_t>(k) < p.angle_names.size() && !p.angle_names[k].empty()
            ? p.angle_names[k]
            : angle_text(a);
    out += fmt::format("<text x=\"{}\" y=\"{}\" class=\"angle-label\">{}</text>\n", px(x), px(y),
                       io::escape_markup(name));
  }
  out += "</g>\n";
}

std::string series_color(const PolarSeries& s, std::size_t si) {
  return s.color.empty() ? kPalette[si % kPalette.size()] : s.color;
}

// One series: runs of present points; a closed series wraps when both ends are present.
void render_series(std::string& out, const PolarSeries& s, const PolarLayout& l, std::size_t index,
                   std::size_t si) {
  const std::string color = series_color(s, si);
  std::vector<std::vector<Point>> runs(1);
  const std::size_t n = s.radius.size();
  std::vector<Point> markers;
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(s.radius[i]) || !std::isfinite(s.angle_deg[i])) {
      if (!runs.back().empty()) runs.emplace_back();
      continue;
    }
    const Point q = to_px(l, s.angle_deg[i], s.radius[i]);
    runs.back().push_back(q);
    markers.push_back(q);
  }
  if (runs.back().empty()) runs.pop_back();
  const bool ends_present = n > 2 && std::isfinite(s.radius.front()) &&
                            std::isfinite(s.angle_deg.front()) && std::isfinite(s.radius.back()) &&
                            std::isfinite(s.angle_deg.back());
  if (s.closed && ends_present && !runs.empty()) {
    if (runs.size() == 1) {
      runs.front().push_back(runs.front().front());
    } else {
      std::vector<Point> joined = runs.back();
      joined.insert(joined.end(), runs.front().begin(), runs.front().end());
      runs.front() = std::move(joined);
      runs.pop_back();
    }
  }
  out += fmt::format("<g class=\"series\" id=\"panel{}-series{}\">\n", index, si);
  for (const std::vector<Point>& run : runs) {
    if (run.size() < 2) continue;
    out +=
        fmt::format("<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"{}\"{} points=\"{}\"/>\n",
                    io::escape_markup(color), px(s.width_px),
                    s.dashed ? " stroke-dasharray=\"6,4\"" : "", points_attr(run));
  }
  if (s.markers) {
    for (const Point& q : markers) {
      out += fmt::format("<circle class=\"marker\" cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"{}\"/>\n",
                         px(q.x), px(q.y), px(kMarkerRadius), io::escape_markup(color));
    }
  }
  out += "</g>\n";
}

// An arrow from the centre, with a head and a label.
void render_arrow(std::string& out, const PolarArrow& a, const PolarLayout& l) {
  const double R = l.r_max * l.scale;
  const double len = a.length * R;
  const double s = std::sin(rad(a.angle_deg));
  const double c = std::cos(rad(a.angle_deg));
  const Point tip{l.cx + len * s, l.cy - len * c};
  const double head = 10.0;
  const double half = 4.5;
  const Point base{tip.x - head * s, tip.y + head * c};
  const Point left{base.x - half * c, base.y - half * s};
  const Point right{base.x + half * c, base.y + half * s};
  out += fmt::format(
      "<g class=\"arrow\" stroke=\"{0}\" fill=\"{0}\">\n<line x1=\"{1}\" y1=\"{2}\" x2=\"{3}\" "
      "y2=\"{4}\" stroke-width=\"2.5\"/>\n<polygon points=\"{5}\"/>\n",
      io::escape_markup(a.color), px(l.cx), px(l.cy), px(base.x), px(base.y),
      points_attr({tip, left, right}));
  if (!a.label.empty()) {
    const double d = len + 12.0;
    out += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\" stroke=\"none\">{}</text>\n",
                       px(l.cx + d * s), px(l.cy - d * c + kFontSize / 3.0),
                       io::escape_markup(a.label));
  }
  out += "</g>\n";
}

// The legend below the circle, one row per labelled series; x0 is the panel block's left edge.
void render_legend(std::string& out, const PolarPanel& p, const PolarLayout& l, double x0) {
  const double R = l.r_max * l.scale;
  double y = l.cy + R + kPad + 4.0;
  out += "<g class=\"legend\">\n";
  for (std::size_t si = 0; si < p.series.size(); ++si) {
    const PolarSeries& s = p.series[si];
    if (s.label.empty()) continue;
    out += fmt::format(
        "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{}\" stroke-width=\"2\"{}/>\n",
        px(x0 + 20.0), px(y), px(x0 + 44.0), px(y), io::escape_markup(series_color(s, si)),
        s.dashed ? " stroke-dasharray=\"6,4\"" : "");
    out += fmt::format("<text x=\"{}\" y=\"{}\">{}</text>\n", px(x0 + 50.0),
                       px(y + kFontSize / 3.0), io::escape_markup(s.label));
    y += kLegendRow;
  }
  out += "</g>\n";
}

void render_panel(std::string& out, const PolarFigure& f, std::size_t index) {
  const PolarPanel& p = f.panels[index];
  const PolarLayout l = polar_layout(f, index);
  out += fmt::format("<g class=\"polar-panel\" id=\"panel{}\">\n", index);
  render_titles(out, p, l);
  render_grid(out, p, l);
  for (std::size_t si = 0; si < p.series.size(); ++si)
    render_series(out, p.series[si], l, index, si);
  for (const PolarArrow& a : p.arrows) render_arrow(out, a, l);
  if (p.legend) render_legend(out, p, l, static_cast<double>(index) * block_width(f));
  out += "</g>\n";
}

}  // namespace

void PolarFigure::validate() const {
  require(!panels.empty(), "no panel");
  require(std::isfinite(panel_size_px) && panel_size_px >= 200.0, "panel size below 200 px");
  for (const PolarPanel& p : panels) {
    require(std::isfinite(p.angle_step_deg) && p.angle_step_deg > 0.0,
            "angle step must be > 0 in panel '" + p.title + "'");
    if (p.r_max) {
      require(std::isfinite(*p.r_max) && *p.r_max > 0.0,
              "r_max must be finite and > 0 in panel '" + p.title + "'");
    }
    if (p.ring_step) {
      require(p.r_max && std::isfinite(*p.ring_step) && *p.ring_step > 0.0 &&
                  *p.r_max / *p.ring_step <= 100.0,
              "ring step must be > 0, with r_max, and give at most 100 rings in panel '" + p.title +
                  "'");
    }
    for (const PolarSeries& s : p.series) {
      require(s.angle_deg.size() == s.radius.size(),
              "series '" + s.label + "' has " + std::to_string(s.angle_deg.size()) +
                  " angles and " + std::to_string(s.radius.size()) + " radii");
      require(std::isfinite(s.width_px) && s.width_px > 0.0,
              "series '" + s.label + "' has a stroke width ≤ 0");
    }
    for (const PolarArrow& a : p.arrows) {
      require(std::isfinite(a.angle_deg), "arrow '" + a.label + "' has no angle");
      require(a.length > 0.0 && a.length <= 1.0,
              "arrow '" + a.label + "' length must be in (0, 1]");
    }
  }
}

PolarLayout polar_layout(const PolarFigure& figure, std::size_t index) {
  if (index >= figure.panels.size()) throw std::out_of_range("polar_layout: no such panel");
  const PolarPanel& p = figure.panels[index];
  const AxisTicks ticks = radial_ticks(p);
  PolarLayout l;
  l.r_max = ticks.hi;
  l.scale = 0.5 * figure.panel_size_px / l.r_max;
  l.cx =
      static_cast<double>(index) * block_width(figure) + kPad + 20.0 + 0.5 * figure.panel_size_px;
  l.cy =
      kFigureTitleHeight + kPanelTitleHeight + kAxisLabelHeight + kPad + 0.5 * figure.panel_size_px;
  for (const double v : ticks.values) {
    if (v > 0.0) l.rings.push_back(v);
  }
  if (l.rings.empty() || l.rings.back() < l.r_max * (1.0 - 1e-9)) l.rings.push_back(l.r_max);
  return l;
}

std::string render_polar_svg(const PolarFigure& figure) {
  figure.validate();
  const double width = static_cast<double>(figure.panels.size()) * block_width(figure);
  const double height = kFigureTitleHeight + block_height(figure);
  std::string out = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} "
      "{1}\" font-family=\"sans-serif\" font-size=\"{2}\">\n",
      px(width), px(height), px(kFontSize));
  out += fmt::format("<rect width=\"{}\" height=\"{}\" fill=\"white\"/>\n", px(width), px(height));
  if (!figure.title.empty()) {
    out += fmt::format(
        "<text x=\"{}\" y=\"22\" text-anchor=\"middle\" font-size=\"15\" "
        "font-weight=\"bold\">{}</text>\n",
        px(0.5 * width), io::escape_markup(figure.title));
  }
  for (std::size_t i = 0; i < figure.panels.size(); ++i) render_panel(out, figure, i);
  out += "</svg>\n";
  return out;
}

void write_polar_svg(const std::filesystem::path& path, const PolarFigure& figure) {
  const std::string text = render_polar_svg(figure);
  io::AtomicFile file(path);
  file.stream() << text;
  file.commit();
}

}  // namespace dynpos::report
