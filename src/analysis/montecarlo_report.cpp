// Monte Carlo documents (analysis/montecarlo.hpp): to JSON and text, and merging shards.

#include <fmt/format.h>

#include <algorithm>
#include <set>

#include "dynpos/analysis/montecarlo.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/io/json_writer.hpp"
#include "dynpos/report/comparison.hpp"
#include "dynpos/report/table.hpp"

namespace dynpos::analysis {
namespace {

using nlohmann::json;

[[noreturn]] void bad_shard(const std::filesystem::path& file, const std::string& problem,
                            const std::string& hint = {}) {
  core::InputLocation where;
  where.file = file.string();
  throw core::InputError(where, problem, hint);
}

// A seed's sample from a shard document; core::InputError naming the file if malformed.
MonteCarloSample sample_from_json(const json& j, const std::filesystem::path& file) {
  MonteCarloSample s;
  try {
    s.seed = j.at("seed").get<std::uint64_t>();
    for (const auto& [key, v] : j.at("values").items()) s.values[key] = v.get<double>();
    for (const auto& [key, v] : j.at("truth").items()) s.truth[key] = v.get<double>();
    for (const auto& note : j.at("notes")) s.notes.push_back(note.get<std::string>());
  } catch (const json::exception& e) {
    bad_shard(file, fmt::format("not a Monte Carlo sample: {}", e.what()),
              "merge the documents `dynpos montecarlo --json` wrote");
  }
  return s;
}

}  // namespace

json to_json(const MonteCarloReport& report) {
  json doc;
  doc["analysis"] = "montecarlo";
  doc["scenario"] = report.scenario;
  doc["seeds"] = {{"first", report.seed_first}, {"last", report.seed_last}};
  doc["shard"] = {{"index", report.shard_index}, {"count", report.shard_count}};
  json samples = json::array();
  for (const MonteCarloSample& s : report.samples) {
    samples.push_back(
        {{"seed", s.seed}, {"values", s.values}, {"truth", s.truth}, {"notes", s.notes}});
  }
  doc["samples"] = std::move(samples);
  json summary = json::object();
  for (const auto& [key, st] : report.summary) {
    summary[key] = {{"n", st.n},
                    {"mean", st.mean},
                    {"std", st.std},
                    {"min", st.min},
                    {"max", st.max},
                    {"truth", io::json_number(st.truth)},
                    {"bias", io::json_number(st.bias)},
                    {"rms_error", io::json_number(st.rms_error)}};
  }
  doc["summary"] = std::move(summary);
  return doc;
}

std::string to_text(const MonteCarloReport& report) {
  const std::size_t runs = report.samples.size();
  std::string out = fmt::format("Monte Carlo: {}, seeds {}..{}", report.scenario, report.seed_first,
                                report.seed_last);
  if (report.shard_count > 1) {
    out += fmt::format(" (shard {}/{}: {} seeds)", report.shard_index, report.shard_count, runs);
  }
  out += fmt::format(", {} run{}\n\n", runs, runs == 1 ? "" : "s");
  report::Table table;
  table.header = {"quantity", "n", "mean", "std", "min", "max", "truth", "bias", "rms error"};
  const auto num = [](double v) { return fmt::format("{:.4g}", v); };
  const auto opt = [&](const std::optional<double>& v) { return v ? num(*v) : std::string("—"); };
  for (const auto& [key, st] : report.summary) {
    table.rows.push_back({key, std::to_string(st.n), num(st.mean), num(st.std), num(st.min),
                          num(st.max), opt(st.truth), opt(st.bias), opt(st.rms_error)});
  }
  out += table.rows.empty() ? "no quantity was identified\n" : report::render_text(table);
  std::size_t noted = 0;
  for (const MonteCarloSample& s : report.samples) noted += s.notes.empty() ? 0 : 1;
  if (noted > 0) {
    out += fmt::format(
        "\n{} seed(s) with an analysis that gave nothing; see \"notes\" in the JSON\n", noted);
  }
  return out;
}

MonteCarloReport merge_montecarlo(const std::vector<std::filesystem::path>& shard_files) {
  if (shard_files.empty()) {
    throw core::InputError::for_option("files", "no shard documents to merge",
                                       "give the JSON files the shards wrote");
  }
  MonteCarloReport report;
  std::set<std::uint64_t> seen;
  for (std::size_t f = 0; f < shard_files.size(); ++f) {
    const std::filesystem::path& file = shard_files[f];
    const json doc = report::load_json_file(file);
    if (!doc.is_object() || doc.value("analysis", "") != "montecarlo") {
      bad_shard(file, "not a Monte Carlo result (no \"analysis\": \"montecarlo\")",
                "merge the documents `dynpos montecarlo --json` wrote");
    }
    MonteCarloReport part;
    try {
      part.scenario = doc.at("scenario").get<std::string>();
      part.seed_first = doc.at("seeds").at("first").get<std::uint64_t>();
      part.seed_last = doc.at("seeds").at("last").get<std::uint64_t>();
    } catch (const json::exception& e) {
      bad_shard(file, fmt::format("not a Monte Carlo result: {}", e.what()));
    }
    if (f == 0) {
      report.scenario = part.scenario;
      report.seed_first = part.seed_first;
      report.seed_last = part.seed_last;
    } else if (part.scenario != report.scenario || part.seed_first != report.seed_first ||
               part.seed_last != report.seed_last) {
      bad_shard(file,
                fmt::format("a shard of {} seeds {}..{}, not of {} seeds {}..{}", part.scenario,
                            part.seed_first, part.seed_last, report.scenario, report.seed_first,
                            report.seed_last),
                "merge the shards of one run only");
    }
    for (const json& j : doc.at("samples")) {
      MonteCarloSample s = sample_from_json(j, file);
      if (s.seed < report.seed_first || s.seed > report.seed_last) {
        bad_shard(file, fmt::format("seed {} is outside the run's seeds {}..{}", s.seed,
                                    report.seed_first, report.seed_last));
      }
      if (!seen.insert(s.seed).second) {
        bad_shard(file, fmt::format("seed {} is in more than one shard", s.seed),
                  "each shard's seeds must be its own");
      }
      report.samples.push_back(std::move(s));
    }
  }
  const std::uint64_t expected = report.seed_last - report.seed_first + 1;
  if (seen.size() != expected) {
    std::uint64_t missing = report.seed_first;
    while (seen.count(missing) != 0) ++missing;
    throw core::InputError::for_option("files",
                                       fmt::format("{} of the {} seeds are missing, the first {}",
                                                   expected - seen.size(), expected, missing),
                                       "merge every shard of the run");
  }
  std::sort(report.samples.begin(), report.samples.end(),
            [](const MonteCarloSample& a, const MonteCarloSample& b) { return a.seed < b.seed; });
  report.summary = summarise(report.samples);
  return report;
}

}  // namespace dynpos::analysis
