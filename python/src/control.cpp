// Control design and the virtual sea trial (thesis chapter 5, the simulator) and the comparison
// of two results, with the CLI's option names; outputs written where the CLI writes them.

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "bind.hpp"
#include "dynpos/analysis/capability.hpp"
#include "dynpos/analysis/capability_transient.hpp"
#include "dynpos/analysis/compare.hpp"
#include "dynpos/analysis/feasibility.hpp"
#include "dynpos/analysis/hybrid_case.hpp"
#include "dynpos/analysis/hybrid_vessel.hpp"
#include "dynpos/analysis/montecarlo.hpp"
#include "dynpos/analysis/options.hpp"
#include "dynpos/analysis/simulate.hpp"

namespace dynpos::python {
namespace {

using namespace dynpos::analysis;

// The hybrid documents list the plots written (as --json does): the JSON returned is the one
// write_outputs writes, made from the files written, not from the report alone. The JSON may go
// into the plots' folder (check_hybrid_case_outputs).
template <typename Request, typename Run>
std::string run_and_write_plots(const Request& request, const Outputs& outputs, Run run) {
  check_hybrid_case_outputs(outputs.figures, outputs.json);
  py::gil_scoped_release release;
  const auto report = run(request);
  Written plots = write_outputs(report, outputs);
  if (!outputs.json.empty() && outputs.json != "-") plots.pop_back();  // the JSON, last
  return to_json(report, plots).dump();
}

void bind_hybrid_case(py::module_& m) {
  using Q = HybridCaseRequest;
  py::class_<Q>(m, "HybridCaseRequest")
      .def(py::init<>())
      .def_property(
          "case", [](const Q& q) { return to_string(q.study_case); },
          [](Q& q, const std::string& name) { q.study_case = hybrid_case_from_string(name); })
      .def_readwrite("no_jumps", &Q::no_jumps)
      .def_readwrite("sampled", &Q::sampled)
      .def_readwrite("seed", &Q::seed)
      .def_readwrite("lambda_", &Q::lambda)
      .def_readwrite("dwell", &Q::dwell_s)
      .def_readwrite("sample_period", &Q::sample_period_s)
      .def_readwrite("noise_power", &Q::noise_power)
      .def_readwrite("end_time", &Q::end_time_s)
      .def_readwrite("heading", &Q::heading_deg)
      .def_readwrite("ki", &Q::ki)
      .def_readwrite("solve_p", &Q::solve_p);
  m.def(
      "run_hybrid_case",
      [](const Q& q, const std::string& json, const std::filesystem::path& out) {
        return run_and_write_plots(q, Outputs{json, out}, run_hybrid_case);
      },
      py::arg("request"), py::arg("json") = "", py::arg("out") = std::filesystem::path());
}

void bind_hybrid_vessel(py::module_& m) {
  using Q = HybridVesselRequest;
  py::class_<Q>(m, "HybridVesselRequest")
      .def(py::init<>())
      .def_property(
          "scenario", [](const Q& q) { return to_string(q.scenario); },
          [](Q& q, const std::string& name) { q.scenario = hybrid_load_from_string(name); })
      .def_readwrite("seed", &Q::seed)
      .def_readwrite("within", &Q::within_m);
  m.def(
      "run_hybrid_vessel",
      [](const Q& q, const std::string& json, const std::filesystem::path& out) {
        return run_and_write_plots(q, Outputs{json, out}, run_hybrid_vessel);
      },
      py::arg("request"), py::arg("json") = "", py::arg("out") = std::filesystem::path());
}

// Labels as "LABEL_A,LABEL_B" or a pair of texts.
using LabelsArg = std::variant<std::string, CompareLabels>;

void bind_compare(py::module_& m) {
  using Q = CompareRequest;
  py::class_<Q>(m, "CompareRequest")
      .def(py::init<>())
      .def_readwrite("a", &Q::a)
      .def_readwrite("b", &Q::b)
      .def_property(
          "format", [](const Q& q) { return to_string(q.format); },
          [](Q& q, const std::string& name) { q.format = table_format_from_string(name); })
      .def_property(
          "labels", [](const Q& q) { return q.labels; },
          [](Q& q, const std::optional<LabelsArg>& labels) {
            if (!labels) return q.labels.reset();
            const auto* text = std::get_if<std::string>(&*labels);
            q.labels = text ? parse_compare_labels(*text) : std::get<CompareLabels>(*labels);
          })
      .def_readwrite("step_tolerance", &Q::step_tolerance_s);
  m.def(
      "run_compare",
      [](const Q& q, const std::string& json) {
        const Outputs outputs{json, {}};
        outputs.check("out", true);
        return run_and_write(q, outputs, run_compare);
      },
      py::arg("request"), py::arg("json") = "");
}

void bind_capability(py::module_& m) {
  using Q = CapabilityRequest;
  py::class_<Q>(m, "CapabilityRequest")
      .def(py::init<>())
      .def_readwrite("level", &Q::level)
      .def_readwrite("vessel", &Q::vessel)
      .def_readwrite("failure", &Q::failure)
      .def_readwrite("site", &Q::site)
      .def_readwrite("hs", &Q::hs)
      .def_readwrite("tp", &Q::tp)
      .def_readwrite("current", &Q::current)
      .def_readwrite("direction_step", &Q::direction_step)
      .def_readwrite("wind_tolerance", &Q::wind_tolerance)
      .def_readwrite("duration", &Q::duration)
      .def_readwrite("settle", &Q::settle)
      .def_readwrite("footprint", &Q::footprint)
      .def_readwrite("footprint_deg", &Q::footprint_deg)
      .def_readwrite("seed", &Q::seed)
      .def_readwrite("jobs", &Q::jobs)
      .def_readwrite("transient", &Q::transient)
      .def_readwrite("rows", &Q::rows)
      .def_readwrite("after", &Q::after)
      .def_readwrite("seeds", &Q::seeds)
      .def_readwrite("observer", &Q::observer);
  m.def(
      "run_capability",
      [](const Q& q, const std::vector<std::string>& given, const std::string& json,
         const std::filesystem::path& out) {
        check_transient_options(q, [&given](std::string_view name) {
          return std::find(given.begin(), given.end(), name) != given.end();
        });
        const Outputs outputs{json, out};
        outputs.check("out", true);
        if (q.transient) return run_and_write(q, outputs, run_capability_transient);
        return run_and_write(q, outputs, run_capability);
      },
      py::arg("request"), py::arg("given"), py::arg("json") = "",
      py::arg("out") = std::filesystem::path());
}

void bind_capability_loads(py::module_& m) {
  using Q = FeasibilityRequest;
  py::class_<Q>(m, "FeasibilityRequest")
      .def(py::init<>())
      .def_readwrite("vessel", &Q::vessel)
      .def_readwrite("loads", &Q::loads)
      .def_readwrite("failure", &Q::failure);
  m.def(
      "run_feasibility",
      [](const Q& q, const std::string& json) {
        const Outputs outputs{json, {}};
        outputs.check("out", true);
        return run_and_write(q, outputs, run_feasibility);
      },
      py::arg("request"), py::arg("json") = "");
}

// The folders written: one for a run, one per scenario for the campaign; [(name, folder)].
std::vector<std::pair<std::string, std::filesystem::path>> simulate(const SimulateRequest& q) {
  py::gil_scoped_release release;
  q.validate();
  const SimulateReport report = run_simulate(q);
  std::vector<std::pair<std::string, std::filesystem::path>> runs;
  if (const auto* one = std::get_if<SimulatedRun>(&report.result)) {
    runs.emplace_back(one->scenario, report.out_dir);
  } else if (const auto* all = std::get_if<std::vector<scenario::RunSummary>>(&report.result)) {
    for (const auto& run : *all) runs.emplace_back(run.name, report.out_dir / run.name);
  }
  return runs;
}

// Seeds as (A, B) or "A..B", a shard as (i, N) or "i/N".
using SeedsArg = std::variant<std::string, std::pair<std::uint64_t, std::uint64_t>>;
using ShardArg = std::variant<std::string, std::pair<std::size_t, std::size_t>>;

void bind_montecarlo(py::module_& m) {
  using Q = MonteCarloRequest;
  py::class_<Q>(m, "MonteCarloRequest")
      .def(py::init<>())
      .def_readwrite("scenario", &Q::scenario)
      .def_property(
          "seeds", [](const Q& q) { return std::pair(q.seeds.first, q.seeds.last); },
          [](Q& q, const SeedsArg& seeds) {
            const auto* text = std::get_if<std::string>(&seeds);
            const auto* pair = std::get_if<1>(&seeds);
            q.seeds = text ? parse_seed_range(*text) : SeedRange{pair->first, pair->second};
          })
      .def_property(
          "shard", [](const Q& q) { return std::pair(q.shard.index, q.shard.count); },
          [](Q& q, const ShardArg& shard) {
            const auto* text = std::get_if<std::string>(&shard);
            const auto* pair = std::get_if<1>(&shard);
            q.shard = text ? parse_shard(*text) : Shard{pair->first, pair->second};
          })
      .def_property(
          "measure", [](const Q& q) { return to_string(q.measure); },
          [](Q& q, const std::string& name) { q.measure = montecarlo_measure_from_string(name); })
      .def_readwrite("jobs", &Q::jobs)
      .def_readwrite("vessel", &Q::vessel_file)
      .def_readwrite("duration", &Q::duration_s)
      .def_readwrite("work_dir", &Q::work_dir);
  m.def(
      "run_montecarlo",
      [](const Q& q, const std::string& json) {
        const Outputs outputs{json, {}};
        outputs.check("out", true);
        return run_and_write(q, outputs, run_montecarlo);
      },
      py::arg("request"), py::arg("json") = "");
}

void bind_simulate(py::module_& m) {
  using Q = SimulateRequest;
  py::class_<Q>(m, "SimulateRequest")
      .def(py::init<>())
      .def_readwrite("scenario", &Q::scenario)
      .def_readwrite("out", &Q::out_dir)
      .def_readwrite("seed", &Q::seed)
      .def_readwrite("vessel", &Q::vessel_file)
      .def_readwrite("duration", &Q::duration_s)
      .def_readwrite("log_rate", &Q::log_rate_hz)
      .def_readwrite("observer", &Q::observer)
      .def_readwrite("jobs", &Q::jobs);
  m.def("run_simulate", &simulate, py::arg("request"));
  m.def("scenarios", [] {
    Q q;
    q.list = true;
    q.scenario = "list";
    const SimulateReport report = run_simulate(q);
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& s : std::get<std::vector<ScenarioListing>>(report.result)) {
      out.emplace_back(s.name, s.description);
    }
    return out;
  });
}

}  // namespace

void bind_control(py::module_& m) {
  bind_hybrid_case(m);
  bind_hybrid_vessel(m);
  bind_compare(m);
  bind_capability(m);
  bind_capability_loads(m);
  bind_simulate(m);
  bind_montecarlo(m);
}

}  // namespace dynpos::python
