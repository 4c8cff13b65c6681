// Identification from logs (thesis chapter 3) and the failure test of DP trials: the requests with
// their CLI option names, and one run function each that writes the outputs the CLI writes and
// returns the --json text.

#include <pybind11/eigen.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "bind.hpp"
#include "dynpos/analysis/agility.hpp"
#include "dynpos/analysis/failure_test.hpp"
#include "dynpos/analysis/four_corner.hpp"
#include "dynpos/analysis/options.hpp"
#include "dynpos/analysis/station_keeping.hpp"
#include "dynpos/analysis/step.hpp"
#include "dynpos/analysis/thrust_map.hpp"
#include "dynpos/analysis/vessel_id.hpp"
#include "dynpos/io/csv_writer.hpp"

namespace dynpos::python {
namespace {

using namespace dynpos::analysis;

void bind_step(py::module_& m) {
  py::class_<StepRequest>(m, "StepRequest")
      .def(py::init<>())
      .def_readwrite("source", &StepRequest::source)
      .def_property(
          "method", [](const StepRequest& q) { return to_string(q.method); },
          [](StepRequest& q, const std::string& name) { q.method = step_method_from_name(name); })
      .def_readwrite("from_", &StepRequest::from_s)
      .def_readwrite("to", &StepRequest::to_s)
      .def_readwrite("step_at", &StepRequest::step_at_s)
      .def_property(
          "derive", [](const StepRequest& q) { return to_string(q.derive); },
          [](StepRequest& q, const std::string& name) { q.derive = step_derive_from_name(name); })
      .def_readwrite("min_step", &StepRequest::min_step)
      .def_readwrite("min_plateau", &StepRequest::min_plateau_s)
      .def_readwrite("segments", &StepRequest::segments_file);
  m.def(
      "run_step",
      [](const StepRequest& q, const std::string& json) {
        const Outputs outputs{json, {}};
        outputs.check("plot", false);
        return run_and_write(q, outputs, run_step);
      },
      py::arg("request"), py::arg("json") = "");
}

void bind_thrust_map(py::module_& m) {
  py::class_<ThrustMapRequest>(m, "ThrustMapRequest")
      .def(py::init<>())
      .def_readwrite("source", &ThrustMapRequest::source)
      .def_readwrite("min_speed", &ThrustMapRequest::min_speed_rpm)
      .def_readwrite("apply", &ThrustMapRequest::apply)
      .def_readwrite("abs_speed", &ThrustMapRequest::abs_speed)
      .def_readwrite("vessel", &ThrustMapRequest::vessel)
      .def_readwrite("out", &ThrustMapRequest::out);
  m.def(
      "run_thrust_map",
      [](ThrustMapRequest q, const std::string& json, const std::string& out) {
        q.out = out;
        q.validate();
        const Outputs outputs{json, {}};
        outputs.check("plot", false);
        check_output_file("out", out);
        return run_and_write(q, outputs, run_thrust_map);
      },
      py::arg("request"), py::arg("json") = "", py::arg("out") = "");
}

void bind_agility(py::module_& m) {
  // window: a list of (T_STEP, T_END, DIR_DEG[, THRUST_PCT[, YAW_PCT]]) tuples; current:
  // (SPEED_MPS, TO_DEG) or None.
  py::class_<AgilityRequest>(m, "AgilityRequest")
      .def(py::init<>())
      .def_readwrite("source", &AgilityRequest::source)
      .def_property(
          "window",
          [](const AgilityRequest& q) {
            py::list out;
            for (const ident::AgilityWindow& w : q.windows) {
              out.append(w.yaw_pct
                             ? py::make_tuple(w.t_step, w.t_end, w.direction_deg, w.magnitude_pct,
                                              *w.yaw_pct)
                             : py::make_tuple(w.t_step, w.t_end, w.direction_deg, w.magnitude_pct));
            }
            return out;
          },
          [](AgilityRequest& q, const std::vector<std::vector<double>>& windows) {
            q.windows.clear();
            for (const std::vector<double>& v : windows) {
              if (v.size() < 3 || v.size() > 5) {
                throw option_error("window",
                                   "a window needs 3 to 5 numbers, has " + std::to_string(v.size()),
                                   "give (T_STEP, T_END, DIR_DEG[, THRUST_PCT[, YAW_PCT]])");
              }
              ident::AgilityWindow w{v[0], v[1], v[2], v.size() > 3 ? v[3] : 100.0, std::nullopt};
              if (v.size() > 4) w.yaw_pct = v[4];
              q.windows.push_back(w);
            }
          })
      .def_property(
          "current",
          [](const AgilityRequest& q) -> std::optional<std::array<double, 2>> {
            if (!q.current) return std::nullopt;
            return std::array<double, 2>{q.current->speed_mps, q.current->to_deg};
          },
          [](AgilityRequest& q, const std::optional<std::array<double, 2>>& c) {
            q.current.reset();
            if (c) q.current = ObservedCurrent{(*c)[0], (*c)[1]};
          })
      .def_readwrite("rpm", &AgilityRequest::use_rpm)
      .def_readwrite("min_response", &AgilityRequest::min_response_pct)
      .def_readwrite("min_demand", &AgilityRequest::min_demand_pct);
  m.def(
      "run_agility",
      [](const AgilityRequest& q, const std::string& json, const std::string& plot) {
        const Outputs outputs{json, plot};
        outputs.check("plot", false);
        return run_and_write(q, outputs, run_agility);
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

void bind_failure_test(py::module_& m) {
  using Q = FailureTestRequest;
  py::class_<Q>(m, "FailureTestRequest")
      .def(py::init<>())
      .def_readwrite("source", &Q::source)
      .def_property(
          "arm", [](const Q& q) { return arm_or_none(q.arm_m); },
          [](Q& q, const py::object& v) { q.arm_m = antenna_arm(v, "arm"); })
      .def_readwrite("rpm", &Q::use_rpm)
      .def_readwrite("from_", &Q::t_from_s)
      .def_readwrite("to", &Q::t_to_s)
      .def_readwrite("pre_window", &Q::pre_window_s)
      .def_readwrite("redistribution_window", &Q::redistribution_window_s)
      .def_readwrite("hold", &Q::hold_s)
      .def_readwrite("response_window", &Q::response_window_s)
      .def_readwrite("max_fall", &Q::max_fall_s)
      .def_readwrite("min_off", &Q::min_off_s);
  m.def(
      "run_failure_test",
      [](const Q& q, const std::string& json) {
        const Outputs outputs{.json = json, .figures = {}};
        outputs.check("plot", false);
        return run_and_write(q, outputs, run_failure_test);
      },
      py::arg("request"), py::arg("json") = "");
}

void bind_vessel_id(py::module_& m) {
  py::class_<VesselIdRequest>(m, "VesselIdRequest")
      .def(py::init<>())
      .def_readwrite("logs", &VesselIdRequest::logs)
      .def_readwrite("vessel", &VesselIdRequest::vessel_file)
      .def_readwrite("holdout", &VesselIdRequest::holdout)
      .def_readwrite("max_rel_sigma", &VesselIdRequest::max_rel_sigma)
      .def_readwrite("max_rel_sigma_fitted", &VesselIdRequest::max_rel_sigma_fitted)
      .def_readwrite("step", &VesselIdRequest::step_s)
      .def_readwrite("sample", &VesselIdRequest::sample_s)
      .def_readwrite("stretch", &VesselIdRequest::stretch_s)
      .def_readwrite("jobs", &VesselIdRequest::jobs);
  m.def(
      "run_vessel_id",
      [](const VesselIdRequest& q, const std::string& out, const std::string& json,
         const std::string& report) {
        const Outputs outputs{.json = json, .figures = report};
        outputs.check("report", true);
        check_output_file("out", out);
        py::gil_scoped_release release;
        const VesselIdReport r = run_vessel_id(q);
        write_outputs(r, out, outputs);
        return to_json(r).dump();
      },
      py::arg("request"), py::arg("out") = "", py::arg("json") = "", py::arg("report") = "");
  py::class_<CompareTrialRequest>(m, "CompareTrialRequest")
      .def(py::init<>())
      .def_readwrite("source", &CompareTrialRequest::source)
      .def_readwrite("vessel", &CompareTrialRequest::vessel_file)
      .def_readwrite("step", &CompareTrialRequest::step_s)
      .def_readwrite("sample", &CompareTrialRequest::sample_s)
      .def_readwrite("stretch", &CompareTrialRequest::stretch_s);
  m.def(
      "run_compare_trial",
      [](const CompareTrialRequest& q, const std::string& json, const std::string& plot) {
        const Outputs outputs{.json = json, .figures = plot};
        outputs.check("plot", false);
        return run_and_write(q, outputs, run_compare_trial);
      },
      py::arg("request"), py::arg("json") = "", py::arg("plot") = "");
}

}  // namespace

void bind_identify(py::module_& m) {
  bind_vessel_id(m);
  bind_step(m);
  bind_thrust_map(m);
  bind_agility(m);
  bind_four_corner(m);
  bind_station_keeping(m);
  bind_failure_test(m);
}

}  // namespace dynpos::python
