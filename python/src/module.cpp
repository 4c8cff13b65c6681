// The compiled part of the Python package `dynpos` (python/dynpos/__init__.py wraps it): logs as
// numpy arrays without copying, the requests of the application layer with their fields, and
// one run function per analysis that returns the report's JSON text (the CLI's --json).

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <string>

#include "dynpos/analysis/leverarm_gnss.hpp"
#include "dynpos/analysis/log_source.hpp"
#include "dynpos/analysis/simulate.hpp"
#include "dynpos/analysis/step.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/io/input_report.hpp"

namespace py = pybind11;
using dynpos::core::Log;

namespace {

// A channel as a read-only numpy view into the log's own storage; `owner` keeps it alive.
py::array view(const std::vector<double>& v, py::handle owner) {
  py::array a(py::dtype::of<double>(), {v.size()}, {sizeof(double)}, v.data(), owner);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

std::shared_ptr<Log> log_from_arrays(py::array_t<double, py::array::c_style> time,
                                     const py::dict& columns, const py::dict& units) {
  auto log = std::make_shared<Log>(std::vector<double>(time.data(), time.data() + time.size()));
  for (const auto& [key, value] : columns) {
    const auto name = key.cast<std::string>();
    const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
    if (!a || a.ndim() != 1 || static_cast<std::size_t>(a.size()) != log->size())
      throw dynpos::core::InputError(
          {{}, {}, {}, name},
          "column '" + name + "' is not a 1-D array of " + std::to_string(log->size()) + " numbers",
          "give one value per time stamp (NaN where missing)");
    std::string unit = units.contains(key) ? units[key].cast<std::string>() : "";
    log->add_channel(name, unit, std::vector<double>(a.data(), a.data() + a.size()));
  }
  return log;
}

void bind_log(py::module_& m) {
  py::class_<Log, std::shared_ptr<Log>>(m, "Log", py::dynamic_attr(),
                                        "A log: one time axis [s], channels in SI.")
      .def_static("from_arrays", &log_from_arrays, py::arg("time"), py::arg("columns"),
                  py::arg("units") = py::dict(),
                  "A log from numpy arrays: time [s] and {role: values} (copied once).")
      .def_property_readonly(
          "time", [](py::object self) { return view(self.cast<const Log&>().time(), self); },
          "Time [s], a read-only view (no copy).")
      .def(
          "__getitem__",
          [](py::object self, const std::string& name) {
            const Log& log = self.cast<const Log&>();
            if (!log.has(name)) throw py::key_error(name);
            return view(log.values(name), self);
          },
          "A channel in SI, a read-only view (no copy); NaN where missing.")
      .def("__contains__", &Log::has)
      .def("__len__", &Log::size)
      .def_property_readonly("channels", &Log::channel_names)
      .def("unit", [](const Log& log, const std::string& name) { return log.channel(name).unit; });
}

void bind_source(py::module_& m) {
  using dynpos::analysis::LogSource;
  py::class_<LogSource>(m, "LogSource")
      .def(py::init<>())
      .def_readwrite("log", &LogSource::log)
      .def_readwrite("map", &LogSource::map_file)
      .def_readwrite("col", &LogSource::columns)
      .def_readwrite("unit", &LogSource::units)
      .def_readwrite("clock_offset", &LogSource::clock_offsets)
      .def_readwrite("max_gap", &LogSource::max_gap_s)
      .def_readwrite("format", &LogSource::format)
      .def_readwrite("strict", &LogSource::strict)
      .def_readwrite("time_format", &LogSource::time_format)
      .def_readwrite("date", &LogSource::date)
      .def_readwrite("time_order", &LogSource::time_order)
      .def_property(
          "memory", [](const LogSource& s) { return std::const_pointer_cast<Log>(s.memory); },
          [](LogSource& s, std::shared_ptr<Log> log) { s.memory = std::move(log); });
  m.def(
      "read_log",
      [](const LogSource& source, std::optional<std::vector<std::string>> roles) {
        dynpos::analysis::LoadedLog loaded;
        {
          py::gil_scoped_release release;
          loaded = source.load([&roles](const std::string& r) {
            return !roles || std::find(roles->begin(), roles->end(), r) != roles->end();
          });
        }
        auto log = std::make_shared<Log>(std::move(loaded.log));
        return py::make_tuple(log, dynpos::io::to_json(loaded.input).dump());
      },
      py::arg("source"), py::arg("roles") = py::none());
}

// A request type with the GIL released while it runs; the report as its JSON text.
template <typename Request, typename Run>
void bind_run(py::module_& m, const char* name, Run run) {
  m.def(
      name,
      [run](const Request& q) {
        std::string json;
        {
          py::gil_scoped_release release;
          json = run(q).dump();
        }
        return json;
      },
      py::arg("request"));
}

void bind_analyses(py::module_& m) {
  using namespace dynpos::analysis;
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
  bind_run<StepRequest>(m, "run_step", [](const StepRequest& q) { return to_json(run_step(q)); });
  py::class_<LeverarmGnssRequest>(m, "LeverarmGnssRequest")
      .def(py::init<>())
      .def_readwrite("source", &LeverarmGnssRequest::source)
      .def_readwrite("method", &LeverarmGnssRequest::method)
      .def_readwrite("imu", &LeverarmGnssRequest::imu)
      .def_readwrite("imu_arm", &LeverarmGnssRequest::imu_arm)
      .def_readwrite("accel", &LeverarmGnssRequest::accel)
      .def_readwrite("antennas", &LeverarmGnssRequest::antennas)
      .def_readwrite("gnss_log", &LeverarmGnssRequest::gnss_log)
      .def_readwrite("nmea", &LeverarmGnssRequest::nmea)
      .def_readwrite("utc_at_zero", &LeverarmGnssRequest::utc_at_zero)
      .def_readwrite("lag", &LeverarmGnssRequest::lag)
      .def_readwrite("time_offset", &LeverarmGnssRequest::time_offset)
      .def_readwrite("estimate_time_offset", &LeverarmGnssRequest::estimate_time_offset)
      .def_readwrite("max_time_offset", &LeverarmGnssRequest::max_time_offset)
      .def_readwrite("pe_window", &LeverarmGnssRequest::pe_window)
      .def_readwrite("gnss_std", &LeverarmGnssRequest::gnss_std);
  bind_run<LeverarmGnssRequest>(m, "run_leverarm_gnss", [](const LeverarmGnssRequest& q) {
    return to_json(run_leverarm_gnss(q));
  });
  py::class_<SimulateRequest>(m, "SimulateRequest")
      .def(py::init<>())
      .def_readwrite("scenario", &SimulateRequest::scenario)
      .def_readwrite("out", &SimulateRequest::out_dir)
      .def_readwrite("seed", &SimulateRequest::seed)
      .def_readwrite("vessel", &SimulateRequest::vessel_file)
      .def_readwrite("duration", &SimulateRequest::duration_s)
      .def_readwrite("log_rate", &SimulateRequest::log_rate_hz);
  m.def("run_simulate", [](const SimulateRequest& q) {
    py::gil_scoped_release release;
    q.validate();
    run_simulate(q);
  });
}

}  // namespace

PYBIND11_MODULE(_dynpos, m) {
  m.doc() = "dynpos: dynamic positioning of ships (compiled part; use the package dynpos)";
  static py::exception<dynpos::core::InputError> input_error(m, "InputError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const dynpos::core::InputError& e) {
      input_error(e.what());
    }
  });
  bind_log(m);
  bind_source(m);
  bind_analyses(m);
}
