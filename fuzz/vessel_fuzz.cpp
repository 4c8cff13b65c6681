// libFuzzer target: the vessel TOML reader (load_vessel_config, which also checks the ranges).

#include "dynpos/core/error.hpp"
#include "dynpos/scenario/vessel_config.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static dynpos::fuzz::InputFile file("vessel.toml");
  try {
    (void)dynpos::scenario::load_vessel_config(file.write(dynpos::fuzz::as_text(data, size)));
  } catch (const dynpos::core::InputError&) {
  }
  return 0;
}
