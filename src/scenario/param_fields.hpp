#pragma once
// A table of named numeric parameters bound to struct fields: read from a TOML section with
// range checks, and written back to JSON for truth.json. One list per section keeps the
// vessel file, the loader and the truth in step.

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "toml_fields.hpp"

namespace dynpos::scenario::detail {

/// One parameter: `key` in the file (its suffix names the file unit), the SI field it fills,
/// and the factor from file unit to SI (e.g. π/180 for a key ending in _deg).
struct ParamField {
  std::string key;
  double* value;
  double lo;  ///< range in file units
  double hi;
  double to_si = 1.0;
};

/// Reads every present key of `fields` from table `t` (absent keys keep their value), rejecting
/// keys not in the list or in `other_keys` (keys the caller reads itself). Throws
/// core::InputError naming file, line and key.
void read_fields(const TomlTable& t, const std::vector<ParamField>& fields,
                 const std::vector<std::string>& other_keys = {});

/// The fields as a JSON object in file units (the same keys the vessel file uses).
nlohmann::json fields_to_json(const std::vector<ParamField>& fields);

/// Key ending in _deg: degrees in the file, radians inside.
constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

}  // namespace dynpos::scenario::detail
