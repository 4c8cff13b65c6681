#pragma once
/// \file
/// Putting the channels of one log on the time axis of another whose clock differs by a
/// constant offset: how the files of a log spread over several files become one log.

#include "dynpos/core/log.hpp"

namespace dynpos::core {

/// Adds every channel of `source` to `target`, resampled onto target's time axis by its own
/// Interp (Log::resample with `options`: no extrapolation, NaN across wide gaps). A source time
/// t_s is the target time t = t_s + clock_offset_s [s].
/// Throws std::invalid_argument if a channel name is taken in `target`, the offset is not
/// finite, or the options are invalid (see Log::resample).
void add_aligned(Log& target, const Log& source, double clock_offset_s,
                 const ResampleOptions& options = {});

}  // namespace dynpos::core
