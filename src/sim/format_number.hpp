#pragma once
// Numbers in error messages of the sim module.

#include <cstdio>
#include <string>

namespace dynpos::sim::detail {

/// A double with `digits` significant digits, for messages ("%.{digits}g").
inline std::string format_number(double value, int digits = 10) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  return buffer;
}

}  // namespace dynpos::sim::detail
