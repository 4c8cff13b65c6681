#pragma once
// Shared pieces of the compiled module _dynpos: one bind function per part of the application
// layer, and the run wrapper every analysis uses (GIL released, outputs written as the CLI does,
// the report returned as its --json text).

#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>

#include "dynpos/analysis/outputs.hpp"
#include "dynpos/io/json_writer.hpp"

namespace dynpos::python {

namespace py = pybind11;

void bind_log(py::module_& m);       // Log, LogSource, read_log
void bind_identify(py::module_& m);  // step, thrust map, agility, four-corner, station keeping
void bind_calib(py::module_& m);     // GNSS and MRU lever arms
void bind_control(py::module_& m);   // hybrid case studies and vessel, simulate, compare
void bind_estimate(py::module_& m);  // the DP observer over a log, the consequence analysis

/// An antenna's lever arm keyword (`key`, BODY [m]): (X, Y) or (X, Y, Z) as a sequence or a
/// numpy array, or the text "X,Y[,Z]" (the CLI's); Z is 0 when left out; None: no arm. Not two
/// or three numbers: option_error naming `key`. A value that is not finite is the request's to
/// refuse (validate), with the CLI's message.
std::optional<Eigen::Vector3d> antenna_arm(const py::handle& value, const char* key);

/// An arm as a numpy array (x, y, z), or None.
py::object arm_or_none(const std::optional<Eigen::Vector3d>& arm);

/// Runs `run(request)` without the GIL, writes what `outputs` names by the analysis'
/// write_outputs (as the CLI does) and returns the report's JSON text. The caller checks the
/// outputs (Outputs::check) before, so that a refused output costs no run.
template <typename Request, typename Run>
std::string run_and_write(const Request& request, const analysis::Outputs& outputs, Run run) {
  py::gil_scoped_release release;
  const auto report = run(request);
  write_outputs(report, outputs);
  return to_json(report).dump();
}

}  // namespace dynpos::python
