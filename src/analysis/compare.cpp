#include "dynpos/analysis/compare.hpp"

#include <fmt/core.h>

#include <string>
#include <tuple>
#include <utility>

#include "dynpos/analysis/options.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/report/table.hpp"

namespace dynpos::analysis {
namespace {

// The labels as given ("A,B"), else the file names, or the paths as given when the names are
// the same.
std::pair<std::string, std::string> labels_of(const CompareRequest& request) {
  const std::string& labels = request.labels;
  if (labels.empty()) {
    if (request.a.filename() == request.b.filename()) {
      return {request.a.string(), request.b.string()};
    }
    return {request.a.filename().string(), request.b.filename().string()};
  }
  const auto comma = labels.find(',');
  if (comma == std::string::npos || labels.find(',', comma + 1) != std::string::npos) {
    throw option_error("labels", "'" + labels + "' is not two labels",
                       "give two labels separated by one comma, e.g. --labels \"Aug 2014,Nov "
                       "2014\"");
  }
  std::string label_a = labels.substr(0, comma), label_b = labels.substr(comma + 1);
  if (label_a.empty() || label_b.empty()) {
    throw option_error("labels", "an empty label in '" + labels + "'",
                       "give two non-empty labels, e.g. --labels \"before,after\"");
  }
  return {label_a, label_b};
}

}  // namespace

void CompareRequest::validate() const {
  if (format != "text" && format != "markdown") {
    throw option_error("format", "unknown format '" + format + "'",
                       "choose text (default) or markdown");
  }
  if (!(step_tolerance_s > 0.0)) {
    throw option_error("step_tolerance", "must be > 0 s", "e.g. --step-tolerance 5");
  }
  labels_of(*this);
}

CompareReport run_compare(const CompareRequest& request) {
  request.validate();
  CompareReport out;
  out.a = request.a;
  out.b = request.b;
  std::tie(out.label_a, out.label_b) = labels_of(request);
  out.format = request.format;
  const nlohmann::json a = report::load_json_file(request.a);
  const nlohmann::json b = report::load_json_file(request.b);
  const std::string kind_a = report::result_kind(a), kind_b = report::result_kind(b);
  if (kind_a != kind_b) {
    throw core::InputError({request.b.string(), {}, {}, {}},
                           fmt::format("cannot compare a '{}' result ({}) with a '{}' result ({})",
                                       kind_a, request.a.string(), kind_b, request.b.string()),
                           "give two results of the same analysis, e.g. two 'identify step' "
                           "JSON files");
  }
  report::ComparisonOptions options;
  options.t_step_match_s = request.step_tolerance_s;
  out.result = report::compare_results(a, b, options);
  for (const report::ComparisonRow& r : out.result.rows) out.common += (r.a && r.b) ? 1 : 0;
  if (out.common == 0) {
    throw core::InputError({request.b.string(), {}, {}, {}},
                           fmt::format("{} and {} have no numeric figure in common",
                                       request.a.string(), request.b.string()),
                           "give two results of the same analysis written with --json");
  }
  return out;
}

nlohmann::json to_json(const CompareReport& report) {
  return report::comparison_json(report.result, report.label_a, report.label_b);
}

std::string to_text(const CompareReport& report) {
  const report::Table table =
      report::comparison_table(report.result, report.label_a, report.label_b);
  const bool md = report.markdown();
  return fmt::format(
             "{} results: {} = {}, {} = {}; {} figures ({} in both, {} only in {}, {} only in "
             "{})\n{}",
             report.result.kind, report.label_a, report.a.string(), report.label_b,
             report.b.string(), report.result.rows.size(), report.common, report.result.only_in_a,
             report.label_a, report.result.only_in_b, report.label_b, md ? "\n" : "") +
         (md ? report::render_markdown(table) : report::render_text(table));
}

}  // namespace dynpos::analysis
