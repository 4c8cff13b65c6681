#pragma once
/// \file
/// Parameter ranges: each parameter group (a model's parameters, a vessel-file section) has one
/// table of its numeric parameters — key, unit, bounds, open or closed ends — that its
/// validate(), the file readers and the documentation all use, so a bound is written once.

#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace dynpos::core {

/// The valid range of one numeric parameter, in the unit of its key.
struct ParamRange {
  std::string key;       ///< as files spell it, unit suffix included ("mass_kg", "max_angle_deg")
  std::string unit;      ///< the key's unit ("kg", "deg", "1" for a pure number)
  double lo = 0.0;       ///< lower bound [unit]
  double hi = 0.0;       ///< upper bound [unit]
  bool lo_open = false;  ///< true: lo itself is outside the range
  bool hi_open = false;  ///< true: hi itself is outside the range
  double to_si = 1.0;    ///< SI value of the field = value of the key × to_si, > 0

  /// True if `value` [unit] is finite and within the bounds.
  bool contains(double value) const noexcept;
  /// True if the SI value of the field is finite and within the bounds × to_si.
  bool contains_si(double value_si) const noexcept;
  /// The bounds as an interval, "[lo, hi]", "(lo, hi]", …, each number as fmt's "{}" prints it.
  std::string interval() const;
};

/// A parameter bound to its field in a struct: the range and the SI value it checks.
template <typename Value>  // double, or const double for reading only
struct BasicParamField {
  ParamRange range;
  Value* value = nullptr;
};
using ParamField = BasicParamField<double>;
using ConstParamField = BasicParamField<const double>;

/// The field type of a table over struct P: double, or const double when P is const (so one
/// table function serves validate() and the file readers).
template <typename P>
using ParamValue = std::conditional_t<std::is_const_v<P>, const double, double>;

/// A named group of parameters, e.g. one section of a vessel file.
template <typename Value>
struct BasicParamSection {
  std::string name;
  std::vector<BasicParamField<Value>> fields;
};
using ParamSection = BasicParamSection<double>;

/// The fields as read-only fields.
std::vector<ConstParamField> as_const(std::span<const ParamField> fields);

/// Throws InputError (column_name "section.key", or "key" when section is empty) for the
/// first field outside its range: "value V is out of range; expected a number in [lo, hi]",
/// V in the key's unit.
void check_ranges(std::string_view section, std::span<const ConstParamField> fields);

}  // namespace dynpos::core
