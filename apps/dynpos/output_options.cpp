// Options several subcommands share, with the checks CLI11 alone does not make: --seed, a
// decimal number 0 … 2⁶⁴−1 (CLI11 reads "-1" into an unsigned seed as 2⁶⁴−1), --json, a file
// name or "-", never empty, and --arm; the outputs of every subcommand, checked together before
// any runs (analysis/output_paths.hpp); and the one printer of normal output.

#include <fmt/core.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "commands.hpp"
#include "dynpos/analysis/option_text.hpp"
#include "dynpos/analysis/output_paths.hpp"
#include "dynpos/core/printable_text.hpp"

namespace dynpos::cli {

CLI::Option* add_seed_option(CLI::App& sub, std::uint64_t& seed, const std::string& help) {
  const CLI::Validator decimal(
      [](std::string& text) -> std::string {
        if (analysis::parse_seed(text)) return {};
        return "'" + text + "' is not a seed: give a whole number from 0 to 18446744073709551615";
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
  return output_file(sub.add_option("--json", json, help)->check(named));
}

CLI::Option* add_arm_option(CLI::App& sub, std::vector<double>& arm_m) {
  return sub
      .add_option("--arm", arm_m,
                  "Lever arm X,Y[,Z] [m] (BODY: forward, starboard, down) of the antenna whose "
                  "position is logged; the position is moved to the control origin, with roll "
                  "and pitch when both are mapped (needed for a Z)")
      ->expected(2, 3)
      ->delimiter(',');
}

namespace {

// The markers: validators that accept anything, found by name.
constexpr const char* kOutputFile = "output-file";
constexpr const char* kOutputFolder = "output-folder";

CLI::Option* mark(CLI::Option* option, const char* name) {
  return option->check(CLI::Validator([](std::string&) { return std::string(); }, "", name));
}

bool marked(const CLI::Option& option, const char* name) {
  try {
    const_cast<CLI::Option&>(option).get_validator(name);
    return true;
  } catch (const CLI::OptionNotFound&) {
    return false;
  }
}

// The request key of an option ("--plot" → "plot"), spelled back by the error message.
std::string key_of(const CLI::Option& option) {
  std::string key = option.get_lnames().empty() ? option.get_name(true) : option.get_lnames()[0];
  std::replace(key.begin(), key.end(), '-', '_');
  return key;
}

// The paths of the options given to `app` and its subcommands.
void collect(const CLI::App& app, analysis::CommandPaths& paths) {
  for (const CLI::Option* option : app.get_options()) {
    if (option->count() == 0) continue;
    const std::string role =
        option->get_lnames().empty() ? option->get_name(true) : "--" + option->get_lnames()[0];
    for (const std::string& value : option->results()) {
      if (marked(*option, kOutputFile)) {
        paths.output_files.push_back({key_of(*option), value});
      } else if (marked(*option, kOutputFolder)) {
        paths.output_folders.push_back({key_of(*option), value});
      } else {
        for (const std::string& path : analysis::paths_in(value))
          paths.inputs.push_back({role, path});
      }
    }
  }
  for (const CLI::App* sub : app.get_subcommands()) collect(*sub, paths);
}

}  // namespace

CLI::Option* output_file(CLI::Option* option) { return mark(option, kOutputFile); }

CLI::Option* output_folder(CLI::Option* option) { return mark(option, kOutputFolder); }

void check_outputs(const CLI::App& app) {
  analysis::CommandPaths paths;
  collect(app, paths);
  analysis::check_command_paths(paths);
}

void print_text(std::FILE* out, const std::string& text) {
  fmt::print(out, "{}", core::printable_text(text));
}

}  // namespace dynpos::cli
