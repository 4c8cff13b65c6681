// dynpos compare A.json B.json: two results of the same analysis side by side (e.g. before and
// after a thruster retrofit, or two trial campaigns), with B − A and (B − A)/|A| per figure.

#include <fmt/core.h>

#include <memory>
#include <string>

#include "commands.hpp"
#include "dynpos/analysis/compare.hpp"

namespace dynpos::cli {
namespace {

// The request, with its text options as given (parsed when the command runs), and the outputs.
struct CompareOptions {
  analysis::CompareRequest request;
  std::string format = analysis::to_string(request.format);
  std::string labels;
  analysis::Outputs outputs;
};

}  // namespace

void register_compare(CLI::App& app) {
  auto opt = std::make_shared<CompareOptions>();
  analysis::CompareRequest& r = opt->request;
  CLI::App* sub = app.add_subcommand(
      "compare", "Compare two results of the same analysis (A.json B.json) side by side");
  sub->add_option("A", r.a, "First result (JSON written with --json)")
      ->required()
      ->check(CLI::ExistingFile);
  sub->add_option("B", r.b, "Second result of the same analysis")
      ->required()
      ->check(CLI::ExistingFile);
  add_json_option(*sub, opt->outputs.json,
                  "Write the comparison as JSON to FILE, or '-' for stdout");
  sub->add_option("--format", opt->format, "Table format: text or markdown")->capture_default_str();
  sub->add_option("--labels", opt->labels,
                  "Names of A and B in the table, comma-separated (default: the file names), "
                  "e.g. \"Aug 2014,Nov 2014\"");
  sub->add_option("--step-tolerance", r.step_tolerance_s,
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
  sub->callback([opt] {
    analysis::CompareRequest& q = opt->request;
    q.format = analysis::table_format_from_string(opt->format);
    if (!opt->labels.empty()) q.labels = analysis::parse_compare_labels(opt->labels);
    write_and_print(analysis::run_compare(q), opt->outputs);
  });
}

}  // namespace dynpos::cli
