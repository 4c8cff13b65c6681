#pragma once
// The option kinds `leverarm gnss` and `leverarm mru` share: an enum by name, and the MRUs'
// acceleration convention.

#include <CLI/CLI.hpp>
#include <map>
#include <string>
#include <utility>

#include "dynpos/calib/mru_observer.hpp"

namespace dynpos::cli {

/// Adds the option `name` bound to the enum `value`, given by the names of `names` (any case);
/// the help shows the request's default by the library's to_string (the names are in `help`).
template <class E>
CLI::Option* add_enum_option(CLI::App& sub, const std::string& name, E& value,
                             std::map<std::string, E> names, const std::string& help) {
  return sub.add_option<E, int>(name, value, help)
      ->transform(CLI::CheckedTransformer(std::move(names), CLI::ignore_case).description(""))
      ->type_name("NAME")
      ->default_str(std::string(to_string(value)));
}

/// The names of calib::MruAccel, for --accel.
inline std::map<std::string, calib::MruAccel> mru_accel_names() {
  std::map<std::string, calib::MruAccel> out;
  for (const auto a : {calib::MruAccel::kKinematic, calib::MruAccel::kSpecificForce})
    out[std::string(calib::to_string(a))] = a;
  return out;
}

}  // namespace dynpos::cli
