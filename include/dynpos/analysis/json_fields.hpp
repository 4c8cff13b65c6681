#pragma once
/// \file
/// The few conventions every report's JSON and tables share: a missing number is null in JSON
/// and "—" in a table, never zero; warnings are {code, message} objects.

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dynpos/core/status.hpp"
#include "dynpos/ident/fit_status.hpp"

namespace dynpos::analysis {

/// The value, or null when absent or not finite (JSON has no NaN), scaled by `scale`.
nlohmann::json number_json(const std::optional<double>& v, double scale = 1.0);

/// The estimate's 1σ, or null.
nlohmann::json sigma_json(const std::optional<ident::Estimate>& e);

/// [{"code": ..., "message": ...}, ...]
nlohmann::json warnings_json(const std::vector<ident::FitWarning>& warnings);

/// The value formatted with the fmt spec (e.g. "{:.2f}"), "—" when absent or NaN, "inf" if ±∞.
std::string number_cell(const std::optional<double>& v, const char* spec);

/// The value of an optional estimate.
std::optional<double> value_of(const std::optional<ident::Estimate>& e);

}  // namespace dynpos::analysis
