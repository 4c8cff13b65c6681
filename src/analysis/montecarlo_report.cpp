// Monte Carlo documents (analysis/montecarlo.hpp): to JSON and text, and merging shards.

#include <fmt/format.h>

#include <algorithm>
#include <set>
#include <string>
#include <utility>
#include <vector>

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

json run_to_json(const MonteCarloRunId& run) {
  return {{"scenario_fnv1a64", run.scenario_fnv1a64},
          {"vessel_fnv1a64", run.vessel_fnv1a64},
          {"duration_s", run.duration_s},
          {"measure", run.measure},
          {"dynpos_version", run.dynpos_version}};
}

// The shard's i/N, checked as --shard is: 1 ≤ i ≤ N.
std::pair<std::size_t, std::size_t> shard_of(const json& doc, const std::filesystem::path& file) {
  std::size_t index = 0, count = 0;
  try {
    index = doc.at("shard").at("index").get<std::size_t>();
    count = doc.at("shard").at("count").get<std::size_t>();
  } catch (const json::exception& e) {
    bad_shard(file, fmt::format("not a Monte Carlo result: {}", e.what()));
  }
  if (count < 1 || index < 1 || index > count) {
    bad_shard(file, fmt::format("shard {}/{} does not exist", index, count),
              "a shard is i/N with 1 ≤ i ≤ N (--shard); merge the documents `dynpos "
              "montecarlo --shard i/N --json` wrote");
  }
  return {index, count};
}

// The items of the run's identity, by name, for naming the one that differs.
std::vector<std::pair<std::string, std::string>> run_items(const MonteCarloRunId& run) {
  return {{"scenario file (FNV-1a 64 of its bytes)", run.scenario_fnv1a64},
          {"vessel file (FNV-1a 64 of its bytes)", run.vessel_fnv1a64},
          {"run length (--duration)", fmt::format("{} s", run.duration_s)},
          {"measurement (--measure)", run.measure},
          {"dynpos version", run.dynpos_version}};
}

MonteCarloRunId run_from_json(const json& doc, const std::filesystem::path& file) {
  if (!doc.contains("run")) {
    bad_shard(file, "the document does not say what run it is of (no \"run\")",
              "it was written by an older dynpos: run the shard again");
  }
  MonteCarloRunId run;
  try {
    const json& j = doc.at("run");
    run.scenario_fnv1a64 = j.at("scenario_fnv1a64").get<std::string>();
    run.vessel_fnv1a64 = j.at("vessel_fnv1a64").get<std::string>();
    run.duration_s = j.at("duration_s").get<double>();
    run.measure = j.at("measure").get<std::string>();
    run.dynpos_version = j.at("dynpos_version").get<std::string>();
  } catch (const json::exception& e) {
    bad_shard(file, fmt::format("not a Monte Carlo result: {}", e.what()));
  }
  return run;
}

// Refuses a shard of another run than the first shard's, naming both files and the item.
void check_same_run(const MonteCarloRunId& first, const std::filesystem::path& first_file,
                    const MonteCarloRunId& part, const std::filesystem::path& file) {
  const auto a = run_items(first), b = run_items(part);
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (a[k].second == b[k].second) continue;
    bad_shard(file,
              fmt::format("a shard of another run than '{}': the {} is {} here, {} there",
                          first_file.string(), a[k].first, b[k].second, a[k].second),
              "merge the shards of one run only: the same scenario and vessel files, "
              "--duration, --measure and dynpos version");
  }
}

}  // namespace

json to_json(const MonteCarloReport& report) {
  json doc;
  doc["analysis"] = "montecarlo";
  doc["scenario"] = report.scenario;
  doc["run"] = run_to_json(report.run);
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
  std::size_t shard_counts = 0;
  std::set<std::uint64_t> seen;
  for (std::size_t f = 0; f < shard_files.size(); ++f) {
    const std::filesystem::path& file = shard_files[f];
    const json doc = report::load_json_file(file);
    if (!doc.is_object() || doc.value("analysis", "") != "montecarlo") {
      bad_shard(file, "not a Monte Carlo result (no \"analysis\": \"montecarlo\")",
                "merge the documents `dynpos montecarlo --json` wrote");
    }
    const auto [shard_index, shard_count] = shard_of(doc, file);
    MonteCarloReport part;
    part.run = run_from_json(doc, file);
    part.shard_count = shard_count;
    try {
      part.scenario = doc.at("scenario").get<std::string>();
      part.seed_first = doc.at("seeds").at("first").get<std::uint64_t>();
      part.seed_last = doc.at("seeds").at("last").get<std::uint64_t>();
    } catch (const json::exception& e) {
      bad_shard(file, fmt::format("not a Monte Carlo result: {}", e.what()));
    }
    if (f == 0) {
      report.scenario = part.scenario;
      report.run = part.run;
      report.seed_first = part.seed_first;
      report.seed_last = part.seed_last;
      shard_counts = shard_count;
    } else if (part.scenario != report.scenario || part.seed_first != report.seed_first ||
               part.seed_last != report.seed_last) {
      bad_shard(file,
                fmt::format("a shard of {} seeds {}..{}, not of {} seeds {}..{}", part.scenario,
                            part.seed_first, part.seed_last, report.scenario, report.seed_first,
                            report.seed_last),
                "merge the shards of one run only");
    } else if (shard_count != shard_counts) {
      bad_shard(file,
                fmt::format("shard {}/{} of a run in {} shards, not {} as '{}'", shard_index,
                            shard_count, shard_count, shard_counts, shard_files[0].string()),
                "merge the shards of one run only");
    }
    check_same_run(report.run, shard_files[0], part.run, file);
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

Written write_outputs(const MonteCarloReport& report, const Outputs& outputs) {
  Written written;
  write_json_output(outputs, to_json(report), written);
  return written;
}

}  // namespace dynpos::analysis
