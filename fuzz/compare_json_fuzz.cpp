// libFuzzer target: the JSON reader of `compare` and the comparison itself. An input is one
// result document, or two separated by a line "%%" (fuzz_input.hpp); each is read as a file,
// compared with itself (every figure equal, none on one side only) and with the other when
// both are of one kind, and the table and JSON of the comparison are made.

#include <cmath>

#include "dynpos/core/error.hpp"
#include "dynpos/report/comparison.hpp"
#include "fuzz_input.hpp"

namespace {

using dynpos::core::InputError;
namespace report = dynpos::report;

std::optional<nlohmann::json> load(dynpos::fuzz::InputFile& file, std::string_view text) {
  try {
    return report::load_json_file(file.write(text));
  } catch (const InputError&) {
    return std::nullopt;
  }
}

void compare(const nlohmann::json& a, const nlohmann::json& b) {
  const auto result = report::compare_results(a, b);
  (void)report::comparison_table(result, "A", "B");
  (void)report::comparison_json(result, "A", "B");
}

// A document against itself: no figure differs and none is missing on one side.
void compare_with_itself(const nlohmann::json& doc) {
  const auto result = report::compare_results(doc, doc);
  if (result.only_in_a != 0 || result.only_in_b != 0) __builtin_trap();
  for (const auto& row : result.rows) {
    if (row.a.has_value() != row.b.has_value() || row.a_text != row.b_text) __builtin_trap();
    if (row.a && !(*row.a == *row.b || (std::isnan(*row.a) && std::isnan(*row.b)))) {
      __builtin_trap();
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static dynpos::fuzz::InputFile file_a("a.json");
  static dynpos::fuzz::InputFile file_b("b.json");
  const auto parts = dynpos::fuzz::split_at_marker(dynpos::fuzz::as_text(data, size));
  const auto a = load(file_a, parts.first.empty() ? parts.second : parts.first);
  if (!a) return 0;
  compare_with_itself(*a);
  if (parts.first.empty()) return 0;
  const auto b = load(file_b, parts.second);
  if (b && report::result_kind(*a) == report::result_kind(*b)) compare(*a, *b);
  return 0;
}
