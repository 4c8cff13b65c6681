#pragma once
// The role prefix of a GNSS antenna: "gnss" and a number, e.g. gnss1.

#include <algorithm>
#include <string>

namespace dynpos::analysis {

inline bool is_gnss_antenna_name(const std::string& p) {
  if (p.size() < 5 || p.rfind("gnss", 0) != 0) return false;
  return std::all_of(p.begin() + 4, p.end(), [](char c) { return c >= '0' && c <= '9'; });
}

}  // namespace dynpos::analysis
