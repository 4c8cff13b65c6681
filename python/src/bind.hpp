#pragma once
// Shared pieces of the compiled module _dynpos: one bind function per part of the application
// layer, and the run wrapper every analysis uses (GIL released, outputs written as the CLI does,
// the report returned as its --json text).

#include <pybind11/pybind11.h>

#include <filesystem>
#include <string>

#include "dynpos/analysis/outputs.hpp"
#include "dynpos/io/json_writer.hpp"

namespace dynpos::python {

namespace py = pybind11;

void bind_log(py::module_& m);       // Log, LogSource, read_log
void bind_identify(py::module_& m);  // step, thrust map, agility, four-corner, station keeping
void bind_calib(py::module_& m);     // GNSS and MRU lever arms
void bind_control(py::module_& m);   // hybrid case studies and vessel, simulate, compare

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
