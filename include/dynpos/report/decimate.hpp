#pragma once
/// \file
/// Min–max decimation of a line for drawing: keep what a pixel column can show.
///
/// A 60 s series at 1 kHz has 60 000 points but a plot is ~800 pixels wide. Within each pixel
/// column a line is drawn as a vertical stroke from its smallest to its largest value, so
/// keeping, for every run of consecutive points that fall in one column, the first, the
/// smallest, the largest and the last point draws the same picture: peaks and jumps survive
/// (unlike taking every n-th point). Gaps (a NaN or infinite coordinate) are kept, one per gap,
/// so a gap still breaks the line.

#include <cstddef>
#include <span>
#include <vector>

namespace dynpos::report {

/// The indices of the points of (x, y) to draw, increasing, at `columns` (≥ 1) pixel columns
/// over [x_lo, x_hi] (x_lo < x_hi). Points left of x_lo share one column and points right of
/// x_hi another, so a line that leaves the range is still drawn up to its edge. x and y must
/// have the same size (the shorter one sets the count otherwise).
std::vector<std::size_t> minmax_decimate(std::span<const double> x, std::span<const double> y,
                                         double x_lo, double x_hi, int columns);

}  // namespace dynpos::report
