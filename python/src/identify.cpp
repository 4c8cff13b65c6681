// Identification from logs (thesis chapter 3): the requests with their CLI option names, and one
// run function each that writes the outputs the CLI writes and returns the --json text.

#include <pybind11/eigen.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <array>
#include <string>
#include <vector>

#include "bind.hpp"
#include "dynpos/analysis/agility.hpp"
#include "dynpos/analysis/four_corner.hpp"
#include "dynpos/analysis/options.hpp"
#include "dynpos/analysis/station_keeping.hpp"
#include "dynpos/analysis/step.hpp"
#include "dynpos/analysis/thrust_map.hpp"
#include "dynpos/io/csv_writer.hpp"

namespace dynpos::python {
namespace {

using namespace dynpos::analysis;

// An analysis with the CLI's --json (and --plot, when `plot` is given): the output targets
// checked first, then the request; the plot written before the JSON, as the command line does.
template <typename Request, typename Report>
std::string run_checked(const Request& q, const std::string& json, Report (*run)(const Request&),
                        const std::string* plot = nullptr) {
  check_output_file("json", json);
  if (plot) check_output_file("plot", *plot);
  return run_to_json(
      q, json,
      [run](const Request& r) {
        r.validate();
        return run(r);
      },
      [plot](const Report& r) {
        if constexpr (requires { write_plot(r, std::filesystem::path()); }) {
          if (plot && !plot->empty()) write_plot(r, *plot);
        }
        return to_json(r);
      });
}

void bind_step(py::module_& m) {
  py::class_<StepRequest>(m, "StepRequest")
      .def(py::init<>())
      .def_readwrite("source", &StepRequest::source)
      .def_readwrite("method", &StepRequest::method)
      .def_readwrite("from_", &StepRequest::from_s)
      .def_readwrite("to", &StepRequest::to_s)
      .def_readwrite("step_at", &StepRequest::step_at_s)
      .def_readwrite("derive", &StepRequest::derive)
      .def_readwrite("min_step", &StepRequest::min_step)
      .def_readwrite("min_plateau", &StepRequest::min_plateau_s)
      .def_readwrite("segments", &StepRequest::segments_file);
  m.def(
      "run_step",
      [](const StepRequest& q, const std::string& json) { return run_checked(q, json, &run_step); },
      py::arg("request"), py::arg("json") = "");
}

void bind_thrust_map(py::module_& m) {
  py::class_<ThrustMapRequest>(m, "ThrustMapRequest")
      .def(py::init<>())
      .def_readwrite("source", &ThrustMapRequest::source)
      .def_readwrite("min_speed", &ThrustMapRequest::min_speed_rpm)
      .def_readwrite("apply", &ThrustMapRequest::apply)
      .def_readwrite("abs_speed", &ThrustMapRequest::abs_speed)
      .def_readwrite("vessel", &ThrustMapRequest::vessel);
  m.def(
      "run_thrust_map",
      [](const ThrustMapRequest& q, const std::string& json, const std::string& out) {
        q.validate();
        if (q.apply && out.empty()) {
          throw option_error("out", "--apply needs --out FILE.csv",
                             "name the CSV to write the computed thrust into");
        }
        check_output_file("json", json);
        return run_to_json(q, json, run_thrust_map, [&out](const ThrustMapReport& r) {
          if (r.applied) io::write_csv(out, r.applied->log);
          return to_json(r);
        });
      },
      py::arg("request"), py::arg("json") = "", py::arg("out") = "");
}

void bind_agility(py::module_& m) {
  py::class_<AgilityRequest>(m, "AgilityRequest")
      .def(py::init<>())
      .def_readwrite("source", &AgilityRequest::source)
      .def_property(
          "window", [](const AgilityRequest&) { return std::vector<std::string>{}; },
          [](AgilityRequest& q, const std::vector<std::string>& specs) {
            q.windows.clear();
            for (const auto& s : specs) q.windows.push_back(parse_agility_window(s, q.source.log));
          })
      .def_property(
          "current", [](const AgilityRequest&) { return std::string{}; },
          [](AgilityRequest& q, const std::string& spec) {
            if (spec.empty()) {
              q.current.reset();
            } else {
              q.current = parse_observed_current(spec);
            }
          })
      .def_readwrite("rpm", &AgilityRequest::use_rpm)
      .def_readwrite("min_response", &AgilityRequest::min_response_pct)
      .def_readwrite("min_demand", &AgilityRequest::min_demand_pct);
  m.def(
      "run_agility",
      [](const AgilityRequest& q, const std::string& json, const std::string& plot) {
        return run_checked(q, json, &run_agility, &plot);
      },
      py::arg("request"), py::arg("json") = "", py::arg("plot") = "");
}

void bind_four_corner(py::module_& m) {
  py::class_<FourCornerRequest>(m, "FourCornerRequest")
      .def(py::init<>())
      .def_readwrite("source", &FourCornerRequest::source)
      .def_readwrite("radius", &FourCornerRequest::radius_m)
      .def_readwrite("heading_tol", &FourCornerRequest::heading_tol_deg)
      .def_property(
          "segment", [](const FourCornerRequest& q) { return to_string(q.segmentation); },
          [](FourCornerRequest& q, const std::string& s) {
            q.segmentation = parse_leg_segmentation(s);
          })
      .def_readwrite("arm", &FourCornerRequest::arm_m)
      .def_readwrite("from_", &FourCornerRequest::t_from_s)
      .def_readwrite("to", &FourCornerRequest::t_to_s);
  m.def(
      "run_four_corner",
      [](const FourCornerRequest& q, const std::string& json, const std::string& plot) {
        const Outputs outputs{.json = json, .figures = plot};
        outputs.check("plot", false);
        return run_and_write(q, outputs, run_four_corner);
      },
      py::arg("request"), py::arg("json") = "", py::arg("plot") = "");
}

void bind_station_keeping(py::module_& m) {
  py::class_<StationKeepingRequest>(m, "StationKeepingRequest")
      .def(py::init<>())
      .def_readwrite("source", &StationKeepingRequest::source)
      .def_readwrite("from_", &StationKeepingRequest::t_from_s)
      .def_readwrite("to", &StationKeepingRequest::t_to_s)
      .def_readwrite("duration", &StationKeepingRequest::duration_s)
      .def_readwrite("per_setpoint", &StationKeepingRequest::per_setpoint)
      .def_readwrite("waves", &StationKeepingRequest::waves)
      .def_readwrite("current", &StationKeepingRequest::current);
  m.def(
      "run_station_keeping",
      [](const StationKeepingRequest& q, const std::string& json) {
        const Outputs outputs{.json = json, .figures = {}};
        outputs.check("plots", true);
        return run_and_write(q, outputs, run_station_keeping);
      },
      py::arg("request"), py::arg("json") = "");
}

}  // namespace

void bind_identify(py::module_& m) {
  bind_step(m);
  bind_thrust_map(m);
  bind_agility(m);
  bind_four_corner(m);
  bind_station_keeping(m);
}

}  // namespace dynpos::python
