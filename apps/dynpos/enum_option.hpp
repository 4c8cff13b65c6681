#pragma once
// An option that takes one of a few names (a method, a convention): read by the library's lookup
// (any case; an unknown name is the library's option error, the same text as in the Python API),
// its default shown from the request.

#include <CLI/CLI.hpp>
#include <string>

namespace dynpos::cli {

/// Adds the option `name` setting the enum `value` by `from_name(text)` (e.g.
/// analysis::accel_from_name); the help shows the request's default by the library's to_string.
template <class E>
CLI::Option* add_enum_option(CLI::App& sub, const std::string& name, E& value,
                             E (*from_name)(const std::string&), const std::string& help) {
  return sub
      .add_option_function<std::string>(
          name, [&value, from_name](const std::string& text) { value = from_name(text); }, help)
      ->type_name("NAME")
      ->default_str(std::string(to_string(value)));
}

}  // namespace dynpos::cli
