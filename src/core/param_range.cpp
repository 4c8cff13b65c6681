#include "dynpos/core/param_range.hpp"

#include <fmt/core.h>

#include <cmath>

#include "dynpos/core/error.hpp"

namespace dynpos::core {
namespace {

bool within(double value, double lo, double hi, bool lo_open, bool hi_open) {
  if (!std::isfinite(value)) return false;
  const bool above = lo_open ? value > lo : value >= lo;
  const bool below = hi_open ? value < hi : value <= hi;
  return above && below;
}

}  // namespace

bool ParamRange::contains(double value) const noexcept {
  return within(value, lo, hi, lo_open, hi_open);
}

bool ParamRange::contains_si(double value_si) const noexcept {
  return within(value_si, lo * to_si, hi * to_si, lo_open, hi_open);
}

std::string ParamRange::interval() const {
  return fmt::format("{}{}, {}{}", lo_open ? '(' : '[', lo, hi, hi_open ? ')' : ']');
}

std::vector<ConstParamField> as_const(std::span<const ParamField> fields) {
  std::vector<ConstParamField> out;
  out.reserve(fields.size());
  for (const ParamField& f : fields) out.push_back({f.range, f.value});
  return out;
}

void check_ranges(std::string_view section, std::span<const ConstParamField> fields) {
  for (const ConstParamField& f : fields) {
    if (f.range.contains_si(*f.value)) continue;
    const std::string key =
        section.empty() ? std::string(f.range.key) : fmt::format("{}.{}", section, f.range.key);
    throw InputError({{}, {}, {}, key},
                     fmt::format("value {} is out of range", *f.value / f.range.to_si),
                     "expected a number in " + f.range.interval());
  }
}

}  // namespace dynpos::core
