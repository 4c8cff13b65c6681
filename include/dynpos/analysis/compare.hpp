#pragma once
/// \file
/// Two results of the same analysis side by side (before and after a thruster retrofit, two
/// trial campaigns): every numeric figure of A and B with B − A and (B − A)/|A|, as a request →
/// report analysis over report/comparison.hpp.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "dynpos/analysis/outputs.hpp"
#include "dynpos/report/comparison.hpp"

namespace dynpos::analysis {

/// The format of the comparison's table.
enum class TableFormat {
  kText,      ///< "text": aligned columns
  kMarkdown,  ///< "markdown": a Markdown table
};

/// "text" or "markdown".
std::string to_string(TableFormat format);

/// The format named `name`; option_error("format") for another name.
TableFormat table_format_from_string(const std::string& name);

/// The names of A and B.
using CompareLabels = std::pair<std::string, std::string>;

/// "LABEL_A,LABEL_B" (one comma, neither label empty); option_error("labels") for other text.
CompareLabels parse_compare_labels(const std::string& text);

/// The options of the comparison; request keys in parentheses (analysis/options.hpp).
struct CompareRequest {
  std::filesystem::path a;                  ///< first result, a JSON file written by an analysis
  std::filesystem::path b;                  ///< second result of the same analysis
  TableFormat format = TableFormat::kText;  ///< the table's format (format)
  /// Names of A and B, neither empty; absent: the file names, or the paths as given when the
  /// names are the same (labels).
  std::optional<CompareLabels> labels;
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
  TableFormat format = TableFormat::kText;  ///< of the table in to_text()
  report::ComparisonResult result;
  std::size_t common = 0;  ///< figures present in both

  /// True when the table is Markdown.
  bool markdown() const { return format == TableFormat::kMarkdown; }
};

/// Validates the request, loads both files and compares them. core::InputError naming the file
/// when it is not valid JSON, when B is a result of another analysis than A, or when the two
/// have no numeric figure in common.
CompareReport run_compare(const CompareRequest& request);

/// The document `compare --json` writes: kind, labels, and one object per figure.
nlohmann::json to_json(const CompareReport& report);

/// What `compare` prints: the kind, the labels and the counts of figures, then the table.
std::string to_text(const CompareReport& report);

/// The JSON (outputs.json); the comparison draws no figure.
Written write_outputs(const CompareReport& report, const Outputs& outputs);

}  // namespace dynpos::analysis
