// Options several subcommands share, with the checks CLI11 alone does not make: --seed, a
// decimal number 0 … 2⁶⁴−1 (CLI11 reads "-1" into an unsigned seed as 2⁶⁴−1), and --json, a
// file name or "-", never empty; the outputs of every subcommand, checked together before
// any runs; and the one printer of normal output.

#include <fmt/core.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "commands.hpp"
#include "dynpos/analysis/options.hpp"
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
  return output_file(sub.add_option("--json", json, help)->check(named));
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

struct NamedPath {
  std::string role;  // how the command line gave it: "--map", "log", "--col output=…@FILE"
  std::string path;
};

// The files a value may name: itself, FILE of ROLE=COLUMN@FILE, FILE of FILE=SECONDS.
std::vector<std::string> paths_in(const std::string& value) {
  std::vector<std::string> out{value};
  if (const auto at = value.rfind('@'); at != std::string::npos)
    out.push_back(value.substr(at + 1));
  if (const auto eq = value.find('='); eq != std::string::npos) out.push_back(value.substr(0, eq));
  return out;
}

void collect(const CLI::App& app, std::vector<NamedPath>& files, std::vector<NamedPath>& folders,
             std::vector<NamedPath>& inputs) {
  for (const CLI::Option* option : app.get_options()) {
    if (option->count() == 0) continue;
    const std::string role =
        option->get_lnames().empty() ? option->get_name(true) : "--" + option->get_lnames()[0];
    for (const std::string& value : option->results()) {
      if (marked(*option, kOutputFile)) {
        files.push_back({key_of(*option), value});
      } else if (marked(*option, kOutputFolder)) {
        folders.push_back({key_of(*option), value});
      } else {
        for (const std::string& path : paths_in(value)) inputs.push_back({role, path});
      }
    }
  }
  for (const CLI::App* sub : app.get_subcommands()) collect(*sub, files, folders, inputs);
}

bool same_file(const struct stat& a, const std::string& path) {
  struct stat b {};
  return ::stat(path.c_str(), &b) == 0 && S_ISREG(b.st_mode) && a.st_dev == b.st_dev &&
         a.st_ino == b.st_ino;
}

}  // namespace

CLI::Option* output_file(CLI::Option* option) { return mark(option, kOutputFile); }

CLI::Option* output_folder(CLI::Option* option) { return mark(option, kOutputFolder); }

void check_outputs(const CLI::App& app) {
  std::vector<NamedPath> files, folders, inputs;
  collect(app, files, folders, inputs);
  for (const NamedPath& f : folders) analysis::check_output_dir(f.role, f.path);
  for (const NamedPath& f : files) {
    // A file in an output folder not made yet (--out D --json D/r.json): nothing is there.
    const auto parent = std::filesystem::path(f.path).parent_path().lexically_normal();
    const bool in_new_folder = !parent.empty() && !std::filesystem::exists(parent) &&
                               std::any_of(folders.begin(), folders.end(), [&](const NamedPath& d) {
                                 return std::filesystem::path(d.path).lexically_normal() == parent;
                               });
    if (in_new_folder) continue;
    analysis::check_output_file(f.role, f.path);
    struct stat out {};
    if (f.path.empty() || f.path == "-" || ::stat(f.path.c_str(), &out) != 0 ||
        !S_ISREG(out.st_mode)) {
      continue;  // nothing there yet, or a device or FIFO written through
    }
    for (const NamedPath& in : inputs) {
      if (!same_file(out, in.path)) continue;
      throw analysis::option_error(
          f.role,
          fmt::format("'{}' is the input '{}' ({}): writing it would destroy the input", f.path,
                      in.path, in.role),
          "write the output to another file");
    }
  }
}

void print_text(std::FILE* out, const std::string& text) {
  fmt::print(out, "{}", core::printable_text(text));
}

}  // namespace dynpos::cli
