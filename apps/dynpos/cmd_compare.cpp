// dynpos compare A.json B.json: two results of the same analysis side by side (e.g. before and
// after a thruster retrofit, or two trial campaigns), with B − A and (B − A)/|A| per figure.

#include <fmt/core.h>

#include <cstdio>
#include <memory>
#include <string>

#include "commands.hpp"
#include "dynpos/analysis/compare.hpp"
#include "dynpos/analysis/options.hpp"
#include "dynpos/io/json_writer.hpp"

namespace dynpos::cli {
namespace {

struct CompareOptions {
  analysis::CompareRequest request;
  std::string json;
};

void run(const CompareOptions& opt) {
  opt.request.validate();
  analysis::check_output_file("json", opt.json);
  const analysis::CompareReport report = analysis::run_compare(opt.request);
  if (!opt.json.empty()) io::write_json(opt.json, analysis::to_json(report));
  std::FILE* out = opt.json == "-" ? stderr : stdout;
  print_text(out, "{}", analysis::to_text(report));
  if (!opt.json.empty() && opt.json != "-") print_text(out, "wrote {}\n", opt.json);
}

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
  add_json_option(*sub, opt->json, "Write the comparison as JSON to FILE, or '-' for stdout");
  sub->add_option("--format", r.format, "Table format: text or markdown")->capture_default_str();
  sub->add_option("--labels", r.labels,
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
  sub->callback([opt] { run(*opt); });
}

}  // namespace dynpos::cli
