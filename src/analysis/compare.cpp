#include "dynpos/analysis/compare.hpp"

#include <fmt/core.h>

#include <string>
#include <tuple>
#include <utility>

#include "dynpos/analysis/options.hpp"
#include "dynpos/core/error.hpp"

namespace dynpos::analysis {
namespace {

// The labels as given, else the file names, or the paths as given when the names are the same.
CompareLabels labels_of(const CompareRequest& request) {
  if (request.labels) return *request.labels;
  if (request.a.filename() == request.b.filename()) return {request.a.string(), request.b.string()};
  return {request.a.filename().string(), request.b.filename().string()};
}

void check_labels(const CompareLabels& labels) {
  if (labels.first.empty() || labels.second.empty()) {
    throw option_error("labels", "an empty label in '" + labels.first + "," + labels.second + "'",
                       "give two non-empty labels, e.g. --labels \"before,after\"");
  }
}

}  // namespace

std::string to_string(TableFormat format) {
  return format == TableFormat::kMarkdown ? "markdown" : "text";
}

TableFormat table_format_from_string(const std::string& name) {
  for (const TableFormat f : {TableFormat::kText, TableFormat::kMarkdown}) {
    if (name == to_string(f)) return f;
  }
  throw option_error("format", "unknown format '" + name + "'",
                     "choose text (default) or markdown");
}

CompareLabels parse_compare_labels(const std::string& text) {
  const auto comma = text.find(',');
  if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos) {
    throw option_error("labels", "'" + text + "' is not two labels",
                       "give two labels separated by one comma, e.g. --labels \"Aug 2014,Nov "
                       "2014\"");
  }
  CompareLabels labels{text.substr(0, comma), text.substr(comma + 1)};
  check_labels(labels);
  return labels;
}

void CompareRequest::validate() const {
  if (!(step_tolerance_s > 0.0)) {
    throw option_error("step_tolerance", "must be > 0 s", "e.g. --step-tolerance 5");
  }
  if (labels) check_labels(*labels);
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

}  // namespace dynpos::analysis
