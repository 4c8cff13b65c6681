#include "dynpos/analysis/json_fields.hpp"

#include <fmt/core.h>

#include <cmath>

namespace dynpos::analysis {

nlohmann::json number_json(const std::optional<double>& v, double scale) {
  return v && std::isfinite(*v) ? nlohmann::json(*v * scale) : nlohmann::json(nullptr);
}

nlohmann::json sigma_json(const std::optional<ident::Estimate>& e) {
  return e ? number_json(e->sigma) : nlohmann::json(nullptr);
}

nlohmann::json warnings_json(const std::vector<ident::FitWarning>& warnings) {
  nlohmann::json out = nlohmann::json::array();
  for (const ident::FitWarning& w : warnings) {
    out.push_back(
        {{"code", std::string(ident::warning_code_name(w.code))}, {"message", w.message}});
  }
  return out;
}

std::string number_cell(const std::optional<double>& v, const char* spec) {
  if (!v || std::isnan(*v)) return "—";  // NaN is the library's missing value
  // A figure that overflowed is shown as what it is, never as the missing mark.
  if (std::isinf(*v)) return *v > 0 ? "inf" : "-inf";
  return fmt::format(fmt::runtime(spec), *v);
}

std::optional<double> value_of(const std::optional<ident::Estimate>& e) {
  return e ? std::optional<double>(e->value) : std::nullopt;
}

}  // namespace dynpos::analysis
