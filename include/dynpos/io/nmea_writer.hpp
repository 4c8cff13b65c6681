#pragma once
/// \file
/// NMEA 0183 sentences written from values: GGA, RMC, VTG, HDT and ROT lines with their
/// checksums, the inverse of parse_nmea_sentence() (io/nmea_sentence.hpp).
///
/// Precision (chosen so a position round-trips to well under 1 mm): time hhmmss.sss; latitude
/// ddmm.mmmmmmm and longitude dddmm.mmmmmmm (1e-7 minute ≈ 0.19 mm, so rounding is ≤ 0.1 mm);
/// altitude and geoid separation to 1 mm; speed in knots and km/h to 3 decimals; course,
/// heading to 0.001°; rate of turn to 0.01°/min. A NaN value writes an empty field. A time of
/// day ≥ 86400 s is written modulo one day (the date is RMC's).

#include <string>
#include <string_view>

#include "dynpos/io/nmea_sentence.hpp"

namespace dynpos::io {

/// "$" + body + "*" + the checksum as two upper-case hex digits (no line terminator).
std::string nmea_frame(std::string_view body);

/// Each returns one sentence without line terminator (files use CR LF between sentences).
/// `talker` is two upper-case letters or digits ("GP", "GN", "HE", …). Throws
/// std::invalid_argument for a bad talker or a value out of range (|lat| > 90°, |lon| > 180°,
/// negative time, quality outside −1…9 where −1 writes an empty field).
std::string format_gga(std::string_view talker, const NmeaGga& gga);
/// RMC in the NMEA 2.3 form (12 fields, with the mode indicator; empty if mode is '\0').
std::string format_rmc(std::string_view talker, const NmeaRmc& rmc);
/// VTG in the NMEA 2.3 form (9 fields): true and magnetic course, speed in knots and km/h.
std::string format_vtg(std::string_view talker, const NmeaVtg& vtg);
std::string format_hdt(std::string_view talker, const NmeaHdt& hdt);
std::string format_rot(std::string_view talker, const NmeaRot& rot);

}  // namespace dynpos::io
