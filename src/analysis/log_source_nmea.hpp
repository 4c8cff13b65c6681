#pragma once
// LogSource for NMEA 0183 captures (private to the module).

#include "dynpos/analysis/log_source.hpp"

namespace dynpos::analysis {

/// True when the source is an NMEA capture: format "nmea", or "auto" and io::looks_like_nmea.
/// Throws core::InputError (option "format") for a format other than auto, csv or nmea.
bool reads_nmea(const LogSource& source);

/// The capture read with io::read_nmea_log (strict as the source says), its channels filtered
/// by `wanted`, and its InputReport; then the roles the column map assigns to further files
/// (add_log_files). Throws core::InputError (option map, col or unit) if the map assigns a role
/// to the capture itself: a capture's roles come from its sentences.
LoadedLog load_nmea(const LogSource& source, const RoleFilter& wanted);

}  // namespace dynpos::analysis
