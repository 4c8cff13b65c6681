#pragma once
/// \file
/// Two results of the same analysis side by side (before and after a thruster retrofit, two
/// trial campaigns): every numeric figure of A and B with B − A and (B − A)/|A|, as a request →
/// report analysis over report/comparison.hpp.

#include <cstddef>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "dynpos/report/comparison.hpp"

namespace dynpos::analysis {

/// The options of the comparison; request keys in parentheses (analysis/options.hpp).
struct CompareRequest {
  std::filesystem::path a;      ///< first result, a JSON file written by an analysis
  std::filesystem::path b;      ///< second result of the same analysis
  std::string format = "text";  ///< table format: "text" or "markdown" (format)
  /// Names of A and B, "LABEL_A,LABEL_B"; empty = the file names, or the paths as given when the
  /// names are the same (labels).
  std::string labels;
  /// Step tests of A and B are the same test if their step times differ by at most this [s],
  /// > 0 (step_tolerance).
  double step_tolerance_s = 5.0;

  /// Throws option_error naming the key of the first bad option.
  void validate() const;
};

/// The comparison, with the inputs the outputs name.
struct CompareReport {
  std::filesystem::path a, b;  ///< the files as given
  std::string label_a, label_b;
  std::string format = "text";  ///< of the table in to_text()
  report::ComparisonResult result;
  std::size_t common = 0;  ///< figures present in both

  /// True when the table is Markdown.
  bool markdown() const { return format == "markdown"; }
};

/// Validates the request, loads both files and compares them. core::InputError naming the file
/// when it is not valid JSON, when B is a result of another analysis than A, or when the two
/// have no numeric figure in common.
CompareReport run_compare(const CompareRequest& request);

/// The document `compare --json` writes: kind, labels, and one object per figure.
nlohmann::json to_json(const CompareReport& report);

/// What `compare` prints: the kind, the labels and the counts of figures, then the table.
std::string to_text(const CompareReport& report);

}  // namespace dynpos::analysis
