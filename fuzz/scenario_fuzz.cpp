// libFuzzer target: the scenario TOML reader (load_scenario, which also checks the values).

#include "dynpos/core/error.hpp"
#include "dynpos/scenario/scenario_spec.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static dynpos::fuzz::InputFile file("scenario.toml");
  try {
    (void)dynpos::scenario::load_scenario(file.write(dynpos::fuzz::as_text(data, size)));
  } catch (const dynpos::core::InputError&) {
  }
  return 0;
}
