// The comparison's JSON and table, and the files written (analysis/compare.hpp).

#include <fmt/core.h>

#include "dynpos/analysis/compare.hpp"
#include "dynpos/report/table.hpp"

namespace dynpos::analysis {

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

Written write_outputs(const CompareReport& report, const Outputs& outputs) {
  Written written;
  write_json_output(outputs, to_json(report), written);
  return written;
}

}  // namespace dynpos::analysis
