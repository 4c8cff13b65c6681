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

/// Runs `run(request)` without the GIL; writes the JSON to `json` when given (as --json does,
/// "-" for standard output) and returns its text. `to_json` turns the report into the document.
template <typename Request, typename Run, typename ToJson>
std::string run_to_json(const Request& request, const std::string& json, Run run, ToJson to_json) {
  py::gil_scoped_release release;
  const nlohmann::json doc = to_json(run(request));
  if (!json.empty()) io::write_json(json, doc);
  return doc.dump();
}

}  // namespace dynpos::python
