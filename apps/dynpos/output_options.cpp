// Options several subcommands share, with the checks CLI11 alone does not make: --seed, a
// decimal number 0 … 2⁶⁴−1 (CLI11 reads "-1" into an unsigned seed as 2⁶⁴−1), and --json, a
// file name or "-", never empty. And the one printer of normal output.

#include <cstdint>
#include <string>

#include "commands.hpp"
#include "dynpos/core/printable_text.hpp"

namespace dynpos::cli {

CLI::Option* add_seed_option(CLI::App& sub, std::uint64_t& seed, const std::string& help) {
  const CLI::Validator decimal(
      [](std::string& text) -> std::string {
        const std::string max = "18446744073709551615";  // 2⁶⁴ − 1
        const bool digits =
            !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
        std::string trimmed = text.substr(std::min(text.find_first_not_of('0'), text.size()));
        if (trimmed.empty()) trimmed = "0";
        if (!digits || trimmed.size() > max.size() ||
            (trimmed.size() == max.size() && trimmed > max)) {
          return "'" + text + "' is not a seed: give a whole number from 0 to " + max;
        }
        return {};
      },
      "UINT64");
  return sub.add_option("--seed", seed, help)->check(decimal)->capture_default_str();
}

CLI::Option* add_json_option(CLI::App& sub, std::string& json, const std::string& help) {
  const CLI::Validator named(
      [](std::string& text) -> std::string {
        return text.empty() ? "an empty name writes nothing: give a FILE, or '-' for stdout"
                            : std::string();
      },
      "FILE|-");
  return sub.add_option("--json", json, help)->check(named);
}

void print_text(std::FILE* out, const std::string& text) {
  fmt::print(out, "{}", core::printable_text(text));
}

}  // namespace dynpos::cli
