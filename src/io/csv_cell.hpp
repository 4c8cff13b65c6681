#pragma once
// Parsing one CSV cell into a number (private to the io module): shared by the row-by-row
// reader and the block parser, so both read every cell alike.

#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "dynpos/core/units.hpp"
#include "text_util.hpp"

namespace dynpos::io::detail {

enum class CellKind { kNumber, kMissing, kText, kNonFinite, kOutOfRange };

/// The common cell of a log, [-]digits[.digits] with at most 19 digits, read from `p` on: the
/// end of the longest such prefix of [p, end) with `value` set, or nullptr (value unset) when
/// there is none or it takes more than Clinger's fast path: an integer mantissa m ≤ 2⁵³ and 10ᵏ
/// with k ≤ 22 are exact doubles, so m / 10ᵏ is the correctly rounded value, the same double
/// std::from_chars gives.
inline const char* scan_plain_decimal(const char* p, const char* const end, double& value) {
  static constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                      1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                      1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  const bool negative = p != end && *p == '-';
  if (negative) ++p;
  std::uint64_t mantissa = 0;
  int digits = 0;
  const char* const int_begin = p;
  for (; p != end && *p >= '0' && *p <= '9'; ++p, ++digits) {
    mantissa = 10 * mantissa + static_cast<std::uint64_t>(*p - '0');
    if (digits >= 19) return nullptr;
  }
  if (p == int_begin) return nullptr;
  int decimals = 0;
  if (p != end && *p == '.') {
    ++p;
    for (; p != end && *p >= '0' && *p <= '9'; ++p, ++digits, ++decimals) {
      mantissa = 10 * mantissa + static_cast<std::uint64_t>(*p - '0');
      if (digits >= 19) return nullptr;
    }
    if (decimals == 0) return nullptr;
  }
  if (mantissa > (std::uint64_t{1} << 53) || decimals > 22) return nullptr;
  const double magnitude = static_cast<double>(mantissa) / kPow10[decimals];
  value = negative ? -magnitude : magnitude;
  return p;
}

/// True (value set) when the whole of `text` is a plain decimal (scan_plain_decimal); false
/// (value unset) for anything else, which from_chars then reads.
inline bool parse_plain_decimal(std::string_view text, double& value) {
  const char* const end = text.data() + text.size();
  double scanned = 0.0;
  const char* const stop = scan_plain_decimal(text.data(), end, scanned);
  if (stop == nullptr || stop != end) return false;
  value = scanned;
  return true;
}

/// What `cell` holds; `value` is set for kNumber. Blank or a declared missing token is missing;
/// numbers are parsed locale-independently ('.' decimal point), a leading '+' allowed.
inline CellKind parse_cell(std::string_view cell, const std::vector<std::string>& missing_tokens,
                           double& value) {
  const std::string_view text = trim(cell);
  if (text.empty()) return CellKind::kMissing;
  for (const auto& token : missing_tokens) {
    if (text == token) return CellKind::kMissing;
  }
  if (parse_plain_decimal(text, value)) return CellKind::kNumber;
  std::string_view digits = text;
  // from_chars does not take a leading '+'; loggers sometimes write one.
  if (digits.size() > 1 && digits.front() == '+' && digits[1] != '-' && digits[1] != '+') {
    digits.remove_prefix(1);
  }
  const char* end = digits.data() + digits.size();
  const auto [ptr, ec] = std::from_chars(digits.data(), end, value);
  if (ec == std::errc::result_out_of_range && ptr == end) return CellKind::kOutOfRange;
  if (ec != std::errc() || ptr != end) return CellKind::kText;
  if (!std::isfinite(value)) return CellKind::kNonFinite;
  return CellKind::kNumber;
}

/// unit.to_si(value), but without adding a zero offset, which would turn -0.0 into +0.0 and
/// break exact write→read round trips.
inline double to_si(const core::Unit& unit, double value) {
  return unit.offset == 0.0 ? value * unit.scale : unit.to_si(value);
}

}  // namespace dynpos::io::detail
