#include "dynpos/io/bag_time.hpp"

#include <array>
#include <utility>

namespace dynpos::io {
namespace {

constexpr std::array<std::pair<BagTime, std::string_view>, 3> kNames = {{
    {BagTime::kAuto, "auto"},
    {BagTime::kHeader, "header"},
    {BagTime::kReceive, "receive"},
}};

}  // namespace

std::string_view bag_time_name(BagTime time) noexcept {
  for (const auto& [t, name] : kNames) {
    if (t == time) return name;
  }
  return "auto";
}

std::optional<BagTime> find_bag_time(std::string_view name) noexcept {
  for (const auto& [t, n] : kNames) {
    if (n == name) return t;
  }
  return std::nullopt;
}

}  // namespace dynpos::io
