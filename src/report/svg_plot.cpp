#include "dynpos/report/svg_plot.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>

#include "dynpos/io/atomic_file.hpp"
#include "dynpos/io/markup.hpp"
#include "dynpos/report/axis_ticks.hpp"
#include "dynpos/report/decimate.hpp"

namespace dynpos::report {
namespace {

// Layout [px]. Every panel (and zoom subplot) is a block of Figure::panel_height_px: a title
// line, the plot area, then the x tick labels and the x-axis label.
constexpr double kMarginLeft = 78.0;
constexpr double kMarginRight = 24.0;
constexpr double kFigureTitleHeight = 34.0;
constexpr double kPanelTitleHeight = 26.0;
constexpr double kPanelBottom = 44.0;
constexpr double kFontSize = 12.0;
// Decimate above this many points per pixel column; below it, every point is drawn.
constexpr double kPointsPerColumn = 4.0;
// Pixel coordinates are clamped to this magnitude so that a wild value cannot produce
// absurd numbers in the file (the plot area clips the line anyway).
constexpr double kMaxPixel = 1.0e6;

constexpr std::array<const char*, 8> kPalette = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                                                 "#9467bd", "#8c564b", "#e377c2", "#7f7f7f"};

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("Figure: " + what);
}

// A pixel coordinate with two decimals, clamped.
std::string px(double v) { return fmt::format("{:.2f}", std::clamp(v, -kMaxPixel, kMaxPixel)); }

// The finite range of the series' x values.
std::pair<double, double> x_data_range(const Panel& panel) {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (const Series& s : panel.series) {
    const std::size_t n = std::min(s.x.size(), s.y.size());
    for (std::size_t i = 0; i < n; ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
      lo = std::min(lo, s.x[i]);
      hi = std::max(hi, s.x[i]);
    }
  }
  return {lo, hi};
}

// The finite range of y over the points with x in [x_lo, x_hi].
std::pair<double, double> y_data_range(const Panel& panel, double x_lo, double x_hi) {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (const Series& s : panel.series) {
    const std::size_t n = std::min(s.x.size(), s.y.size());
    for (std::size_t i = 0; i < n; ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
      if (s.x[i] < x_lo || s.x[i] > x_hi) continue;
      lo = std::min(lo, s.y[i]);
      hi = std::max(hi, s.y[i]);
    }
  }
  return {lo, hi};
}

AxisTicks axis_ticks(const Axis& axis, double data_lo, double data_hi, int target) {
  if (axis.min && axis.max) return nice_ticks(*axis.min, *axis.max, target, false);
  const double lo = axis.min.value_or(data_lo);
  const double hi = axis.max.value_or(data_hi);
  if (!std::isfinite(lo) || !std::isfinite(hi)) return nice_ticks(0.0, 1.0, target, true);
  AxisTicks ticks = nice_ticks(lo, hi, target, true);
  // Keep a fixed end exactly where it was asked for.
  if (axis.min || axis.max) {
    ticks = nice_ticks(axis.min.value_or(ticks.lo), axis.max.value_or(ticks.hi), target, false);
  }
  return ticks;
}

class Writer {
 public:
  explicit Writer(const Figure& figure) : figure_(figure) {}

  std::string render() {
    std::size_t blocks = 0;
    for (const Panel& p : figure_.panels) blocks += p.zoom ? 2 : 1;
    const double height =
        kFigureTitleHeight + static_cast<double>(blocks) * figure_.panel_height_px;
    out_ += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    out_ += fmt::format(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" "
        "viewBox=\"0 0 {0} {1}\" font-family=\"sans-serif\" font-size=\"{2}\">\n",
        px(figure_.width_px), px(height), kFontSize);
    out_ += fmt::format("<rect x=\"0\" y=\"0\" width=\"{}\" height=\"{}\" fill=\"white\"/>\n",
                        px(figure_.width_px), px(height));
    out_ += fmt::format(
        "<text x=\"{}\" y=\"22\" text-anchor=\"middle\" font-size=\"15\" "
        "font-weight=\"bold\">{}</text>\n",
        px(figure_.width_px / 2.0), io::escape_markup(figure_.title));
    double top = kFigureTitleHeight;
    for (const Panel& panel : figure_.panels) {
      const auto [x_lo, x_hi] = x_data_range(panel);
      const AxisTicks x_ticks = axis_ticks(panel.x_axis, x_lo, x_hi, 10);
      panel_block(panel, panel.title, top, x_ticks, panel.y_axis, true);
      top += figure_.panel_height_px;
      if (panel.zoom) {
        const XRange z = *panel.zoom;
        const AxisTicks zoom_x = nice_ticks(z.lo, z.hi, 10, false);
        Axis zoom_y = panel.y_axis;
        zoom_y.min.reset();
        zoom_y.max.reset();
        const std::string unit = panel.x_axis.unit.empty() ? "" : " " + panel.x_axis.unit;
        panel_block(panel,
                    fmt::format("{} — zoom on {} … {}{}", panel.title,
                                format_tick(z.lo, zoom_x.decimals + 1),
                                format_tick(z.hi, zoom_x.decimals + 1), unit),
                    top, zoom_x, zoom_y, false);
        top += figure_.panel_height_px;
      }
    }
    out_ += "</svg>\n";
    return std::move(out_);
  }

 private:
  // One panel block with its top edge at `top`, over the x-axis `x_ticks`; is_main draws the
  // zoom band of the panel (if any).
  void panel_block(const Panel& panel, const std::string& title, double top,
                   const AxisTicks& x_ticks, const Axis& y_axis, bool is_main) {
    const double left = kMarginLeft;
    const double right = figure_.width_px - kMarginRight;
    const double plot_top = top + kPanelTitleHeight;
    const double bottom = top + figure_.panel_height_px - kPanelBottom;
    const auto [y_lo, y_hi] = y_data_range(panel, x_ticks.lo, x_ticks.hi);
    const AxisTicks y_ticks = axis_ticks(y_axis, y_lo, y_hi, 5);
    const auto X = [&](double x) {
      return left + (x - x_ticks.lo) / (x_ticks.hi - x_ticks.lo) * (right - left);
    };
    const auto Y = [&](double y) {
      return bottom - (y - y_ticks.lo) / (y_ticks.hi - y_ticks.lo) * (bottom - plot_top);
    };
    const int id = ++block_count_;

    out_ += fmt::format("<g class=\"panel\" id=\"panel{}\">\n", id);
    out_ +=
        fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\" font-size=\"13\">{}</text>\n",
                    px((left + right) / 2.0), px(top + 17.0), io::escape_markup(title));
    out_ += fmt::format(
        "<clipPath id=\"clip{}\"><rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"/></clipPath>\n",
        id, px(left), px(plot_top), px(right - left), px(bottom - plot_top));
    // Grid and ticks.
    for (const double v : x_ticks.values) {
      const double xp = X(v);
      out_ += fmt::format(
          "<line x1=\"{0}\" y1=\"{1}\" x2=\"{0}\" y2=\"{2}\" stroke=\"#e0e0e0\" "
          "stroke-width=\"1\"/>\n",
          px(xp), px(plot_top), px(bottom));
      out_ += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", px(xp),
                          px(bottom + 16.0), io::escape_markup(format_tick(v, x_ticks.decimals)));
    }
    for (const double v : y_ticks.values) {
      const double yp = Y(v);
      out_ += fmt::format(
          "<line x1=\"{0}\" y1=\"{1}\" x2=\"{2}\" y2=\"{1}\" stroke=\"#e0e0e0\" "
          "stroke-width=\"1\"/>\n",
          px(left), px(yp), px(right));
      out_ += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"end\">{}</text>\n", px(left - 6.0),
                          px(yp + 4.0), io::escape_markup(format_tick(v, y_ticks.decimals)));
    }
    // Zoom band.
    if (is_main && panel.zoom) {
      const double z0 = std::clamp(X(panel.zoom->lo), left, right);
      const double z1 = std::clamp(X(panel.zoom->hi), left, right);
      out_ += fmt::format(
          "<rect class=\"zoom-band\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" "
          "fill=\"#808080\" fill-opacity=\"0.15\"/>\n",
          px(z0), px(plot_top), px(std::max(z1 - z0, 1.0)), px(bottom - plot_top));
    }
    // Event markers.
    for (const double m : panel.x_markers) {
      if (!std::isfinite(m) || m < x_ticks.lo || m > x_ticks.hi) continue;
      out_ += fmt::format(
          "<line class=\"marker\" x1=\"{0}\" y1=\"{1}\" x2=\"{0}\" y2=\"{2}\" stroke=\"#555555\" "
          "stroke-width=\"1\" stroke-dasharray=\"2,3\"/>\n",
          px(X(m)), px(plot_top), px(bottom));
    }
    // Series.
    const int columns = std::max(1, static_cast<int>(right - left));
    std::size_t palette = 0;
    std::vector<std::pair<std::string, const Series*>> legend;
    for (const Series& s : panel.series) {
      const std::string color = s.color.empty() ? kPalette[palette++ % kPalette.size()] : s.color;
      if (!s.label.empty()) legend.emplace_back(color, &s);
      std::vector<std::size_t> idx;
      const std::size_t n = std::min(s.x.size(), s.y.size());
      if (static_cast<double>(n) > kPointsPerColumn * columns) {
        idx = minmax_decimate(s.x, s.y, x_ticks.lo, x_ticks.hi, columns);
      } else {
        idx.resize(n);
        for (std::size_t i = 0; i < n; ++i) idx[i] = i;
      }
      std::string d;
      bool pen_down = false;
      std::size_t in_segment = 0;
      for (const std::size_t i : idx) {
        if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) {
          if (pen_down && in_segment == 1) d += " l0,0";  // a lone point shows as a dot
          pen_down = false;
          continue;
        }
        d += fmt::format("{}{},{}", pen_down ? " L" : (d.empty() ? "M" : " M"), px(X(s.x[i])),
                         px(Y(s.y[i])));
        in_segment = pen_down ? in_segment + 1 : 1;
        pen_down = true;
      }
      if (pen_down && in_segment == 1) d += " l0,0";
      if (d.empty()) continue;
      out_ += fmt::format(
          "<path class=\"series\" clip-path=\"url(#clip{})\" fill=\"none\" stroke=\"{}\" "
          "stroke-width=\"{}\" stroke-linejoin=\"round\" stroke-linecap=\"round\"{} d=\"{}\"/>\n",
          id, io::escape_markup(color), fmt::format("{:.2f}", s.width_px),
          s.dashed ? " stroke-dasharray=\"6,4\"" : "", d);
    }
    // Frame and axis labels.
    out_ += fmt::format(
        "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#333333\" "
        "stroke-width=\"1\"/>\n",
        px(left), px(plot_top), px(right - left), px(bottom - plot_top));
    out_ += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n",
                        px((left + right) / 2.0), px(bottom + 34.0),
                        io::escape_markup(panel.x_axis.text()));
    const double y_mid = (plot_top + bottom) / 2.0;
    out_ += fmt::format(
        "<text x=\"{0}\" y=\"{1}\" text-anchor=\"middle\" transform=\"rotate(-90 {0} {1})\">{2}"
        "</text>\n",
        px(left - 56.0), px(y_mid), io::escape_markup(y_axis.text()));
    // Legend, top right inside the plot area.
    if (panel.legend && !legend.empty()) {
      std::size_t longest = 0;
      for (const auto& entry : legend) longest = std::max(longest, entry.second->label.size());
      const double w = 36.0 + 6.5 * static_cast<double>(longest);
      const double h = 8.0 + 16.0 * static_cast<double>(legend.size());
      const double x0 = right - w - 8.0;
      const double y0 = plot_top + 8.0;
      out_ += fmt::format(
          "<g class=\"legend\"><rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"white\" "
          "fill-opacity=\"0.85\" stroke=\"#999999\" stroke-width=\"0.5\"/>\n",
          px(x0), px(y0), px(w), px(h));
      for (std::size_t k = 0; k < legend.size(); ++k) {
        const double yk = y0 + 14.0 + 16.0 * static_cast<double>(k);
        const Series& s = *legend[k].second;
        out_ += fmt::format(
            "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{}\" stroke-width=\"2\"{}/>\n",
            px(x0 + 6.0), px(yk - 4.0), px(x0 + 26.0), px(yk - 4.0),
            io::escape_markup(legend[k].first), s.dashed ? " stroke-dasharray=\"6,4\"" : "");
        out_ += fmt::format("<text x=\"{}\" y=\"{}\">{}</text>\n", px(x0 + 31.0), px(yk),
                            io::escape_markup(s.label));
      }
      out_ += "</g>\n";
    }
    out_ += "</g>\n";
  }

  const Figure& figure_;
  std::string out_;
  int block_count_ = 0;
};

}  // namespace

std::string Axis::text() const { return unit.empty() ? label : label + " [" + unit + "]"; }

void Figure::validate() const {
  require(std::isfinite(width_px) && width_px >= 200.0, "width_px must be >= 200");
  require(std::isfinite(panel_height_px) && panel_height_px >= 100.0,
          "panel_height_px must be >= 100");
  for (const Panel& p : panels) {
    const std::string where = "panel '" + p.title + "': ";
    for (const Series& s : p.series) {
      require(s.x.size() == s.y.size(), where + "series '" + s.label + "' has " +
                                            std::to_string(s.x.size()) + " x values but " +
                                            std::to_string(s.y.size()) + " y values");
      require(std::isfinite(s.width_px) && s.width_px > 0.0,
              where + "series '" + s.label + "' needs a stroke width > 0");
    }
    for (const Axis* a : {&p.x_axis, &p.y_axis}) {
      require(!a->min || std::isfinite(*a->min), where + "axis '" + a->label + "' min not finite");
      require(!a->max || std::isfinite(*a->max), where + "axis '" + a->label + "' max not finite");
      require(!(a->min && a->max) || *a->min < *a->max,
              where + "axis '" + a->label + "' needs min < max");
    }
    if (p.zoom) {
      require(std::isfinite(p.zoom->lo) && std::isfinite(p.zoom->hi) && p.zoom->lo < p.zoom->hi,
              where + "zoom range needs finite lo < hi");
    }
  }
}

std::string render_svg(const Figure& figure) {
  figure.validate();
  return Writer(figure).render();
}

void write_svg(const std::filesystem::path& path, const Figure& figure) {
  const std::string text = render_svg(figure);
  io::AtomicFile file(path);
  file.stream() << text;
  file.commit();
}

}  // namespace dynpos::report
