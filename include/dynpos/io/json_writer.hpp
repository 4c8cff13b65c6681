#pragma once
/// \file
/// JSON output: machine-readable results for `--json FILE` and `--json -` (stdout).
///
/// Missing numbers are JSON null (JSON has no NaN or infinity); use json_number() and
/// json_numbers() to convert doubles that may be missing.

#include <filesystem>
#include <optional>
#include <span>

#include <nlohmann/json.hpp>

namespace dynpos::io {

/// Writes `doc` pretty-printed (2-space indent, trailing newline) to `path` atomically, or to
/// stdout when `path` is "-". Throws std::runtime_error with the path and the reason on
/// failure.
void write_json(const std::filesystem::path& path, const nlohmann::json& doc);

/// The JSON text write_json() produces for `doc`.
std::string json_text(const nlohmann::json& doc);

/// A double as JSON: a number, or null when it is missing (NaN) or infinite.
nlohmann::json json_number(double value);

/// An optional double as JSON: null when absent, else as json_number().
nlohmann::json json_number(const std::optional<double>& value);

/// An array of doubles, each as json_number().
nlohmann::json json_numbers(std::span<const double> values);

}  // namespace dynpos::io
