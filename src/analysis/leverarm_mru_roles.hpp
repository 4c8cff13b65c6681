#pragma once
// The MRU roles of `leverarm mru`: which channels hold an MRU's accelerations. Private to the
// analysis module (its run and its demo section).

#include <string>
#include <vector>

#include "dynpos/core/log.hpp"

namespace dynpos::analysis::detail {

/// Whether `role` is mruK.ax, mruK.ay or mruK.az.
inline bool is_mru_accel_role(const std::string& role) {
  if (role.rfind("mru", 0) != 0) return false;
  const auto dot = role.find('.');
  if (dot == std::string::npos) return false;
  const std::string ch = role.substr(dot + 1);
  return ch == "ax" || ch == "ay" || ch == "az";
}

/// The MRU names K with all of mruK.ax/ay/az in `log`, in channel order.
inline std::vector<std::string> mru_names(const core::Log& log) {
  std::vector<std::string> out;
  for (const std::string& c : log.channel_names()) {
    if (!is_mru_accel_role(c) || c.substr(c.find('.') + 1) != "ax") continue;
    const std::string name = c.substr(0, c.find('.'));
    if (log.has(name + ".ay") && log.has(name + ".az")) out.push_back(name);
  }
  return out;
}

}  // namespace dynpos::analysis::detail
