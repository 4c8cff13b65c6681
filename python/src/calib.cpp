// Lever-arm calibration (thesis chapter 4): GNSS antennas and MRUs, with the CLI's option names;
// the run functions write the JSON and plots where the CLI does and return the --json text.

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <string>

#include "bind.hpp"
#include "dynpos/analysis/leverarm_gnss.hpp"
#include "dynpos/analysis/leverarm_mru.hpp"
#include "dynpos/analysis/options.hpp"

namespace dynpos::python {
namespace {

using namespace dynpos::analysis;

void bind_leverarm_gnss(py::module_& m) {
  using Q = LeverarmGnssRequest;
  py::class_<Q>(m, "LeverarmGnssRequest")
      .def(py::init<>())
      .def_readwrite("source", &Q::source)
      .def_readwrite("method", &Q::method)
      .def_readwrite("imu", &Q::imu)
      .def_readwrite("imu_arm", &Q::imu_arm)
      .def_readwrite("accel", &Q::accel)
      .def_readwrite("antennas", &Q::antennas)
      .def_readwrite("gnss_log", &Q::gnss_log)
      .def_readwrite("nmea", &Q::nmea)
      .def_readwrite("utc_at_zero", &Q::utc_at_zero)
      .def_readwrite("init", &Q::init)
      .def_readwrite("w1", &Q::w1)
      .def_readwrite("w2", &Q::w2)
      .def_readwrite("gamma", &Q::gamma)
      .def_readwrite("L", &Q::L)
      .def_readwrite("init_p0", &Q::init_p0)
      .def_readwrite("adaptive_rate", &Q::adaptive_rate)
      .def_readwrite("lag", &Q::lag)
      .def_readwrite("time_offset", &Q::time_offset)
      .def_readwrite("estimate_time_offset", &Q::estimate_time_offset)
      .def_readwrite("max_time_offset", &Q::max_time_offset)
      .def_readwrite("converged_from", &Q::converged_from)
      .def_readwrite("pe_window", &Q::pe_window)
      .def_readwrite("gnss_std", &Q::gnss_std);
  m.def(
      "run_leverarm_gnss",
      [](const Q& q, const std::string& json, const std::string& plots) {
        q.validate();
        check_output_file("json", json);
        return run_to_json(q, json, run_leverarm_gnss, [&plots](const LeverarmGnssReport& r) {
          if (!plots.empty()) write_figures(r, plots);
          return to_json(r);
        });
      },
      py::arg("request"), py::arg("json") = "", py::arg("plots") = "");
}

void bind_leverarm_mru(py::module_& m) {
  using Q = LeverarmMruRequest;
  py::class_<Q>(m, "LeverarmMruRequest")
      .def(py::init<>())
      .def_readwrite("source", &Q::source)
      .def_readwrite("mru_log", &Q::mru_log)
      .def_readwrite("accel", &Q::accel)
      .def_readwrite("method", &Q::method)
      .def_readwrite("window_s", &Q::window_s)
      .def_readwrite("tau_s", &Q::tau_s)
      .def_readwrite("w1", &Q::w1);
  m.def(
      "run_leverarm_mru",
      [](const Q& q, const std::string& json, const std::string& plots) {
        q.validate();
        check_output_file("json", json);
        return run_to_json(q, json, run_leverarm_mru, [&plots](const LeverarmMruReport& r) {
          if (!plots.empty()) write_figures(r, plots);
          return to_json(r);
        });
      },
      py::arg("request"), py::arg("json") = "", py::arg("plots") = "");
}

}  // namespace

void bind_calib(py::module_& m) {
  bind_leverarm_gnss(m);
  bind_leverarm_mru(m);
}

}  // namespace dynpos::python
