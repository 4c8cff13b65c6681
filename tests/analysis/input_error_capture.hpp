#pragma once
// The analysis tests' one way to catch the InputError a call throws.

#include <gtest/gtest.h>

#include <string>

#include "dynpos/core/error.hpp"

namespace dynpos::analysis::testing {

/// The InputError `f()` throws; a test failure (and an empty error) if it throws none.
template <class F>
core::InputError input_error(F&& f) {
  try {
    f();
  } catch (const core::InputError& e) {
    return e;
  }
  ADD_FAILURE() << "expected a core::InputError";
  return core::InputError({}, "");
}

/// The request key of the option error `f()` throws, or "no error".
template <class F>
std::string option_key_of(F&& f) {
  try {
    f();
  } catch (const core::InputError& e) {
    return e.option();
  }
  return "no error";
}

}  // namespace dynpos::analysis::testing
