#pragma once
/// \file
/// Option values as a command line gives them, as text: NAME=VALUE pairs, lists of numbers,
/// seeds and lever arms read, and X,Y,Z written back for the help. Errors name the request key
/// (analysis/options.hpp).

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace dynpos::analysis {

/// "NAME=VALUE" as (NAME, VALUE), split at the first '='; nothing when there is no '=' or
/// NAME or VALUE is empty.
std::optional<std::pair<std::string, std::string>> split_assignment(const std::string& text);

/// The comma-separated numbers of `text`, the value of the option `key` (no items for "");
/// option_error(key) naming the first item that is not a number.
std::vector<double> parse_numbers(const std::string& text, const std::string& key);

/// `text` as a seed: decimal digits only (leading zeros allowed), 0 … 2⁶⁴−1; nothing for an
/// empty text, a sign, a space or an overflow.
std::optional<std::uint64_t> parse_seed(std::string_view text);

/// "X,Y,Z" of `v`, each number in its shortest exact form, as parse_vec3 reads it back.
std::string vec3_text(const Eigen::Vector3d& v);

/// The lever arm of the numbers X,Y or X,Y,Z [m] (Z = 0 when two are given), the value of the
/// option `key`; nothing for none, option_error(key) for another count.
std::optional<Eigen::Vector3d> arm_from_numbers(const std::vector<double>& xyz_m,
                                                const std::string& key);

}  // namespace dynpos::analysis
