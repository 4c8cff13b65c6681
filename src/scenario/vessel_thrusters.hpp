#pragma once
// The vessel file's thruster layout, [[thruster]] units (private; docs/vessel-file.md).

#include <toml++/toml.h>
#include <vector>

#include "dynpos/model/thruster_unit.hpp"
#include "toml_fields.hpp"

namespace dynpos::scenario::detail {

/// Each [[thruster]] table of `doc` as a unit, defaults filled in, in file order. Throws
/// core::InputError naming the file, line and key of the first bad entry (a missing or unknown
/// key, a value out of range, a name used twice, a key another type has).
std::vector<model::ThrusterUnit> read_thruster_units(const toml::table& doc, const TomlTable& root);

}  // namespace dynpos::scenario::detail
