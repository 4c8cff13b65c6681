#pragma once
// Fixes of a position joined at the log's rows (private): a position reference logged at 1 Hz
// in a 10 Hz log samples wave motion of a 7 s period 7 times a cycle; its largest distances
// (footprint, peak) and the times it crosses a radius are those of the rows only once the rows
// between the fixes are filled as the motion went, which a cubic spline does to within 0.2 %
// of the wave's amplitude (docs/theory.md, "Failure test").

#include <vector>

namespace dynpos::ident::detail {

/// x with its missing samples (NaN) between two valid ones at most `max_gap_s` apart filled by
/// the natural cubic spline through the valid samples of each run of such gaps (t increasing).
/// Samples before the first, after the last valid one and in longer gaps stay missing; a run
/// of two valid samples is joined by a line.
std::vector<double> fill_between_fixes(const std::vector<double>& t, const std::vector<double>& x,
                                       double max_gap_s);

}  // namespace dynpos::ident::detail
