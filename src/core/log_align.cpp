#include "dynpos/core/log_align.hpp"

#include <stdexcept>

namespace dynpos::core {

void add_aligned(Log& target, const Log& source, double clock_offset_s,
                 const ResampleOptions& options) {
  if (!std::isfinite(clock_offset_s)) {
    throw std::invalid_argument("add_aligned: the clock offset is not finite");
  }
  if (source.empty()) {
    for (const Channel& c : source.channels()) {
      target.add_channel(c.name, c.unit, std::vector<double>(target.size(), kMissing), c.interp);
    }
    return;
  }
  std::vector<double> shifted_s = source.time();
  for (double& t : shifted_s) t += clock_offset_s;
  Log shifted(std::move(shifted_s));
  for (const Channel& c : source.channels())
    shifted.add_channel(c.name, c.unit, c.values, c.interp);
  if (target.empty()) {
    for (const Channel& c : source.channels()) target.add_channel(c.name, c.unit, {}, c.interp);
    return;
  }
  const Log aligned = shifted.resample(target.time(), options);
  for (const Channel& c : aligned.channels()) {
    target.add_channel(c.name, c.unit, c.values, c.interp);
  }
}

}  // namespace dynpos::core
