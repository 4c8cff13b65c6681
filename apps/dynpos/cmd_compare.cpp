// dynpos compare A.json B.json: two results of the same analysis side by side (e.g. before and
// after a thruster retrofit, or two trial campaigns), with B − A and (B − A)/|A| per figure.

#include <fmt/core.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

#include "commands.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/io/json_writer.hpp"
#include "dynpos/report/comparison.hpp"
#include "dynpos/report/table.hpp"

namespace dynpos::cli {
namespace {

struct CompareOptions {
  std::filesystem::path a, b;
  std::string json;
  std::string format = "text";
  std::string labels;
  double t_step_match_s = 5.0;
};

core::InputError option_error(const std::string& option, const std::string& problem,
                              const std::string& hint = {}) {
  return core::InputError({{}, {}, {}, option}, problem, hint);
}

std::pair<std::string, std::string> parse_labels(const CompareOptions& opt) {
  if (opt.labels.empty()) {
    // The file names, or the paths as given when the names are the same.
    if (opt.a.filename() == opt.b.filename()) return {opt.a.string(), opt.b.string()};
    return {opt.a.filename().string(), opt.b.filename().string()};
  }
  const auto comma = opt.labels.find(',');
  if (comma == std::string::npos || opt.labels.find(',', comma + 1) != std::string::npos) {
    throw option_error("--labels", "'" + opt.labels + "' is not two labels",
                       "give two labels separated by one comma, e.g. --labels \"Aug 2014,Nov "
                       "2014\"");
  }
  std::string la = opt.labels.substr(0, comma), lb = opt.labels.substr(comma + 1);
  if (la.empty() || lb.empty()) {
    throw option_error("--labels", "an empty label in '" + opt.labels + "'",
                       "give two non-empty labels, e.g. --labels \"before,after\"");
  }
  return {la, lb};
}

void run_compare(const CompareOptions& opt) {
  if (opt.format != "text" && opt.format != "markdown") {
    throw option_error("--format", "unknown format '" + opt.format + "'",
                       "choose text (default) or markdown");
  }
  if (!(opt.t_step_match_s > 0.0)) {
    throw option_error("--step-tolerance", "must be > 0 s", "e.g. --step-tolerance 5");
  }
  if (!opt.json.empty() && opt.json != "-") {
    const auto parent = std::filesystem::path(opt.json).parent_path();
    if (!parent.empty() && !std::filesystem::is_directory(parent)) {
      throw option_error("--json", "folder '" + parent.string() + "' does not exist",
                         "create it first, or use --json - for stdout");
    }
  }
  const auto [label_a, label_b] = parse_labels(opt);
  const nlohmann::json a = report::load_json_file(opt.a);
  const nlohmann::json b = report::load_json_file(opt.b);
  const std::string kind_a = report::result_kind(a), kind_b = report::result_kind(b);
  if (kind_a != kind_b) {
    throw core::InputError({opt.b.string(), {}, {}, {}},
                           fmt::format("cannot compare a '{}' result ({}) with a '{}' result ({})",
                                       kind_a, opt.a.string(), kind_b, opt.b.string()),
                           "give two results of the same analysis, e.g. two 'identify step' "
                           "JSON files");
  }
  report::ComparisonOptions copt;
  copt.t_step_match_s = opt.t_step_match_s;
  const report::ComparisonResult result = report::compare_results(a, b, copt);
  std::size_t common = 0;
  for (const auto& r : result.rows) common += (r.a && r.b) ? 1 : 0;
  if (common == 0) {
    throw core::InputError(
        {opt.b.string(), {}, {}, {}},
        fmt::format("{} and {} have no numeric figure in common", opt.a.string(), opt.b.string()),
        "give two results of the same analysis written with --json");
  }
  if (!opt.json.empty())
    io::write_json(opt.json, report::comparison_json(result, label_a, label_b));

  const report::Table table = report::comparison_table(result, label_a, label_b);
  std::FILE* out = opt.json == "-" ? stderr : stdout;
  const bool md = opt.format == "markdown";
  fmt::print(out,
             "{} results: {} = {}, {} = {}; {} figures ({} in both, {} only in {}, {} only in "
             "{})\n{}",
             result.kind, label_a, opt.a.string(), label_b, opt.b.string(), result.rows.size(),
             common, result.only_in_a, label_a, result.only_in_b, label_b, md ? "\n" : "");
  fmt::print(out, "{}", md ? report::render_markdown(table) : report::render_text(table));
  if (!opt.json.empty() && opt.json != "-") fmt::print(out, "wrote {}\n", opt.json);
}

}  // namespace

void register_compare(CLI::App& app) {
  auto opt = std::make_shared<CompareOptions>();
  CLI::App* sub = app.add_subcommand(
      "compare", "Compare two results of the same analysis (A.json B.json) side by side");
  sub->add_option("A", opt->a, "First result (JSON written with --json)")
      ->required()
      ->check(CLI::ExistingFile);
  sub->add_option("B", opt->b, "Second result of the same analysis")
      ->required()
      ->check(CLI::ExistingFile);
  sub->add_option("--json", opt->json, "Write the comparison as JSON to FILE, or '-' for stdout");
  sub->add_option("--format", opt->format, "Table format: text or markdown")->capture_default_str();
  sub->add_option("--labels", opt->labels,
                  "Names of A and B in the table, comma-separated (default: the file names), "
                  "e.g. \"Aug 2014,Nov 2014\"");
  sub->add_option("--step-tolerance", opt->t_step_match_s,
                  "Step tests of A and B are the same test if their step times differ by at "
                  "most this [s]")
      ->capture_default_str();
  sub->footer(
      "Recognises the analysis from the keys of each result (or its \"analysis\" key) and pairs "
      "items by a natural key: legs, lever arms and thrusters by name, agility directions by "
      "direction and case, step tests by the nearest step time, other arrays by position. Every "
      "numeric figure is shown as A, B, B - A and (B - A)/|A| in %; a missing figure is \"—\". "
      "Any two JSON documents of the same shape compare the same way. Example: dynpos compare "
      "aug/steps.json nov/steps.json --labels \"Aug 2014,Nov 2014\"");
  sub->callback([opt] { run_compare(*opt); });
}

}  // namespace dynpos::cli
