#pragma once
// Reading a table of numeric parameters (core/param_range.hpp) from a TOML section with its
// range checks, and writing it back to JSON for truth.json. One table per section keeps the
// vessel file, the loader, validation, the truth and the docs in step.

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "dynpos/core/param_range.hpp"
#include "toml_fields.hpp"

namespace dynpos::scenario::detail {

/// Reads every present key of `fields` from table `t` (absent keys keep their value), checks it
/// against its range and stores it in SI (× to_si), rejecting keys not in the list or in
/// `other_keys` (keys the caller reads itself). Throws core::InputError naming file, line and
/// key.
void read_fields(const TomlTable& t, const std::vector<core::ParamField>& fields,
                 const std::vector<std::string>& other_keys = {});

/// The fields as a JSON object in file units (the same keys the vessel file uses).
nlohmann::json fields_to_json(const std::vector<core::ParamField>& fields);

/// Key ending in _deg: degrees in the file, radians inside.
constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

}  // namespace dynpos::scenario::detail
