#pragma once
/// \file
/// Line plots of time series as SVG: panels stacked vertically, each with axes and nice ticks,
/// labels with units, a legend, event markers and an optional zoom subplot over an x-range.
///
/// A Figure is a plain description; render_svg() turns it into the SVG text and write_svg()
/// writes that atomically (the file appears complete or not at all). Rendering is deterministic:
/// the same figure gives the same bytes.
///
/// Drawing rules:
///  - A NaN or infinite x or y is a gap: the line stops there and starts again at the next
///    finite point. A missing value is never drawn as zero.
///  - Axes without a fixed range cover the finite data (y only over the shown x-range), widened
///    to the nearest ticks. Lines are clipped to the plot area.
///  - A series with far more points than the plot has pixel columns is min–max decimated
///    (decimate.hpp), which keeps peaks and jumps.
///  - A series may repeat an x value (e.g. the value before and after a jump at the same
///    instant); the line then draws the jump as a vertical stroke.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace dynpos::report {

/// One line: points (x[i], y[i]).
struct Series {
  std::string label;      ///< legend text; empty keeps the series out of the legend
  std::vector<double> x;  ///< same size as y
  std::vector<double> y;
  std::string color;      ///< a CSS colour, e.g. "#1f77b4"; empty: the default palette in order
  double width_px = 1.5;  ///< stroke width [px], > 0
  bool dashed = false;
};

/// An axis of a panel.
struct Axis {
  std::string label;          ///< e.g. "Time"
  std::string unit;           ///< e.g. "s"; the axis reads "Time [s]"; empty: no brackets
  std::optional<double> min;  ///< fixed lower end; absent: from the data
  std::optional<double> max;  ///< fixed upper end; absent: from the data

  /// "label [unit]", or the label alone when the unit is empty.
  std::string text() const;
};

/// A closed x-interval [lo, hi], lo < hi.
struct XRange {
  double lo = 0.0;
  double hi = 1.0;
};

/// One subplot.
struct Panel {
  std::string title;
  Axis x_axis;
  Axis y_axis;
  std::vector<Series> series;
  std::vector<double> x_markers;  ///< vertical dashed lines at these x (events, steps)
  std::optional<XRange> zoom;     ///< adds a subplot below over this x-range, y from its data
  bool legend = true;             ///< draw a legend of the labelled series
};

/// A figure: a title and panels stacked top to bottom (a zoom subplot follows its panel).
struct Figure {
  std::string title;
  double width_px = 900.0;         ///< [px], ≥ 200
  double panel_height_px = 260.0;  ///< height of each panel and zoom subplot [px], ≥ 100
  std::vector<Panel> panels;

  /// Throws std::invalid_argument naming the first problem: a size below the minimum, a
  /// series whose x and y differ in size, a stroke width ≤ 0, a fixed axis range with
  /// min ≥ max, or a zoom range with lo ≥ hi or a non-finite end.
  void validate() const;
};

/// The SVG document of the figure (UTF-8). Throws std::invalid_argument if it is invalid.
std::string render_svg(const Figure& figure);

/// Renders the figure and writes it to `path` atomically. Throws std::invalid_argument if the
/// figure is invalid and std::runtime_error with the path and the reason if writing fails.
void write_svg(const std::filesystem::path& path, const Figure& figure);

}  // namespace dynpos::report
