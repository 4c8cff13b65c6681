#include "dynpos/hybrid/trace.hpp"

#include <stdexcept>
#include <string>

namespace dynpos::hybrid {

const core::Channel& Trace::channel(std::string_view name) const {
  for (const core::Channel& c : channels) {
    if (c.name == name) return c;
  }
  std::string known;
  for (const core::Channel& c : channels) known += (known.empty() ? "" : ", ") + c.name;
  throw std::out_of_range("Trace: no channel '" + std::string(name) + "' (channels: " + known +
                          ")");
}

bool Trace::has(std::string_view name) const noexcept {
  for (const core::Channel& c : channels) {
    if (c.name == name) return true;
  }
  return false;
}

}  // namespace dynpos::hybrid
