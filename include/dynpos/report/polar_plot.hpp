#pragma once
/// \file
/// Polar charts as SVG, drawn like a compass: angle 0 at the top (north, or "ahead" for a
/// direction relative to the vessel), angles increasing clockwise (90 to the right). Used for
/// the thrust agility plots (thesis figures 3.1–3.3): response time on the radial axis against
/// the commanded thrust direction.
///
/// A PolarFigure holds one or more polar panels side by side, each with a radial grid of
/// labelled rings, spokes with angle labels, series (polylines through (angle, radius) points
/// with markers, closed around the circle when asked), arrows (e.g. wind and current) and a
/// legend. Rendering is deterministic: the same figure gives the same bytes.
///
/// Drawing rules:
///  - A NaN or infinite radius or angle is a gap: the line stops there and no marker is drawn;
///    a missing value is never drawn at the centre. A closed series closes only when its first
///    and last points are both present.
///  - The radial axis starts at 0; its end is `r_max` when given, else the largest finite
///    radius of the panel widened to the next nice tick. Radii beyond it are drawn on the rim.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace dynpos::report {

/// One series: points at (angle_deg[i], radius[i]).
struct PolarSeries {
  std::string label;              ///< legend text; empty keeps it out of the legend
  std::vector<double> angle_deg;  ///< compass angle [deg], 0 at the top, clockwise
  std::vector<double> radius;     ///< same size as angle_deg, in the radial axis' unit
  std::string color;              ///< CSS colour; empty: the default palette in order
  double width_px = 1.5;          ///< stroke width [px], > 0
  bool dashed = false;
  bool closed = true;   ///< join the last point to the first
  bool markers = true;  ///< a dot at every present point
};

/// An arrow from the centre in a compass direction, e.g. the wind or the current.
struct PolarArrow {
  std::string label;       ///< drawn at the arrow head, e.g. "wind 3.3 m/s"
  double angle_deg = 0.0;  ///< direction the arrow points [deg], 0 at the top, clockwise
  double length = 0.5;     ///< as a fraction (0, 1] of the outer ring's radius
  std::string color = "#2ca02c";
};

/// One polar chart.
struct PolarPanel {
  std::string title;
  std::string radial_label;     ///< e.g. "Response time"
  std::string radial_unit;      ///< e.g. "s"
  std::optional<double> r_max;  ///< outer ring; absent: from the data
  /// With r_max: a labelled ring at every multiple of this (e.g. 1 for one ring per DP
  /// capability number); absent: about five nice rings.
  std::optional<double> ring_step;
  double angle_step_deg = 45.0;          ///< spokes and angle labels every this many degrees, > 0
  std::vector<std::string> angle_names;  ///< optional names for the spokes from 0 clockwise,
                                         ///< e.g. {"ahead", "", "stb", ...}; else degrees
  std::vector<PolarSeries> series;
  std::vector<PolarArrow> arrows;
  bool legend = true;
};

/// Panels side by side, left to right.
struct PolarFigure {
  std::string title;
  double panel_size_px = 460.0;  ///< width and height of the square plot area of a panel, ≥ 200
  std::vector<PolarPanel> panels;

  /// Throws std::invalid_argument naming the first problem: no panel, a size below the
  /// minimum, a series whose angle and radius differ in size, a stroke width ≤ 0, r_max ≤ 0 or
  /// not finite, a ring step ≤ 0 or without r_max or giving more than 100 rings, an angle step
  /// ≤ 0, an arrow length outside (0, 1].
  void validate() const;
};

/// Where a panel is drawn: its centre and scale, so that a point (θ, r) lands at
/// x = cx + r·scale·sin θ, y = cy − r·scale·cos θ (SVG y grows downwards).
struct PolarLayout {
  double cx = 0.0;            ///< centre [px]
  double cy = 0.0;            ///< centre [px]
  double scale = 1.0;         ///< pixels per radial unit
  double r_max = 1.0;         ///< outer ring [radial unit]
  std::vector<double> rings;  ///< radii of the labelled rings [radial unit], increasing
};

/// The layout of panel `index` of a valid figure. Throws std::out_of_range for a bad index.
PolarLayout polar_layout(const PolarFigure& figure, std::size_t index);

/// The SVG document of the figure (UTF-8). Throws std::invalid_argument if it is invalid.
std::string render_polar_svg(const PolarFigure& figure);

/// Renders the figure and writes it to `path` atomically. Throws std::invalid_argument if the
/// figure is invalid and std::runtime_error with the path and the reason if writing fails.
void write_polar_svg(const std::filesystem::path& path, const PolarFigure& figure);

}  // namespace dynpos::report
