#include "dynpos/analysis/option_text.hpp"

#include <fmt/core.h>

#include <charconv>
#include <sstream>
#include <stdexcept>

#include "dynpos/analysis/options.hpp"

namespace dynpos::analysis {

std::optional<std::pair<std::string, std::string>> split_assignment(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size()) return std::nullopt;
  return std::pair{text.substr(0, eq), text.substr(eq + 1)};
}

std::vector<double> parse_numbers(const std::string& text, const std::string& key) {
  std::vector<double> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    try {
      std::size_t used = 0;
      out.push_back(std::stod(item, &used));
      if (used != item.size() && item.find_first_not_of(' ', used) != std::string::npos) {
        throw std::invalid_argument(item);
      }
    } catch (const std::exception&) {
      throw option_error(key, "'" + item + "' in '" + text + "' is not a number",
                         "give comma-separated numbers");
    }
  }
  return out;
}

std::optional<std::uint64_t> parse_seed(std::string_view text) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string_view::npos) {
    return std::nullopt;
  }
  std::uint64_t seed = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), seed);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return seed;
}

std::string vec3_text(const Eigen::Vector3d& v) {
  return fmt::format("{},{},{}", v(0), v(1), v(2));
}

std::optional<Eigen::Vector3d> arm_from_numbers(const std::vector<double>& xyz_m,
                                                const std::string& key) {
  if (xyz_m.empty()) return std::nullopt;
  if (xyz_m.size() > 3 || xyz_m.size() < 2) {
    throw option_error(key, fmt::format("{} numbers are not an arm", xyz_m.size()),
                       "give X,Y or X,Y,Z [m]");
  }
  return Eigen::Vector3d(xyz_m[0], xyz_m[1], xyz_m.size() > 2 ? xyz_m[2] : 0.0);
}

}  // namespace dynpos::analysis
