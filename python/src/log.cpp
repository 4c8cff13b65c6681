// Logs as numpy arrays without copying, logs built from arrays, and the log options every
// analysis shares (LogSource) with read_log.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bind.hpp"
#include "dynpos/analysis/log_source.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/core/log.hpp"
#include "dynpos/io/csv_reader.hpp"
#include "dynpos/io/input_report.hpp"

namespace dynpos::python {
namespace {

using core::Log;

// A channel as a read-only numpy view into the log's own storage; `owner` keeps it alive.
py::array view(const std::vector<double>& v, py::handle owner) {
  py::array a(py::dtype::of<double>(), {v.size()}, {sizeof(double)}, v.data(), owner);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

// A column's values: NaN is a missing value; ±inf is refused (an overflow upstream, or a
// sentinel), naming the column and the row.
std::vector<double> numbers(const py::handle& values, std::size_t n, const std::string& name) {
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(values);
  if (!a || a.ndim() != 1 || static_cast<std::size_t>(a.size()) != n) {
    throw core::InputError(
        {{}, {}, {}, name},
        "column '" + name + "' is not a 1-D array of " + std::to_string(n) + " numbers",
        "give one value per time stamp (NaN where missing)");
  }
  std::vector<double> out(a.data(), a.data() + a.size());
  const auto inf = std::find_if(out.begin(), out.end(), [](double v) { return std::isinf(v); });
  if (inf != out.end()) {
    throw core::InputError(
        {{}, {}, {}, name},
        fmt::format("row {} of column '{}' is {}", inf - out.begin(), name, *inf),
        "give finite numbers (NaN where missing)");
  }
  return out;
}

// The time axis: finite and strictly increasing, else an InputError naming the first bad row.
std::vector<double> time_axis(const py::handle& time) {
  const auto t = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(time);
  if (!t || t.ndim() != 1) {
    throw core::InputError({{}, {}, {}, "time"}, "time is not a 1-D array of numbers",
                           "give the time stamps in seconds");
  }
  std::vector<double> out(t.data(), t.data() + t.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (!std::isfinite(out[i])) {
      throw core::InputError({{}, {}, {}, "time"}, fmt::format("row {} is {}", i, out[i]),
                             "give finite time stamps in seconds");
    }
    if (i > 0 && !(out[i] > out[i - 1])) {
      throw core::InputError(
          {{}, {}, {}, "time"},
          fmt::format("row {} ({} s) is {} row {} ({} s)", i, out[i],
                      out[i] == out[i - 1] ? "the same time as" : "earlier than", i - 1,
                      out[i - 1]),
          "give strictly increasing time stamps (sort the rows, drop repeated ones)");
    }
  }
  return out;
}

// `value` as a dict, or an InputError naming the keyword.
py::dict dict_argument(const py::handle& value, const char* keyword) {
  if (!py::isinstance<py::dict>(value)) {
    throw core::InputError({{}, {}, {}, keyword},
                           std::string("a ") +
                               py::str(value.get_type().attr("__name__")).cast<std::string>() +
                               " is not a dict",
                           "give {name: values}");
  }
  return py::reinterpret_borrow<py::dict>(value);
}

std::string text_argument(const py::handle& value, const std::string& keyword) {
  if (!py::isinstance<py::str>(value)) {
    throw core::InputError({{}, {}, {}, keyword}, "a name or unit that is not text",
                           "give text, e.g. \"m/s\"");
  }
  return value.cast<std::string>();
}

std::shared_ptr<Log> log_from_arrays(const py::handle& time, const py::handle& columns_arg,
                                     const py::handle& units_arg) {
  const py::dict columns = dict_argument(columns_arg, "columns");
  const py::dict units = dict_argument(units_arg, "units");
  auto log = std::make_shared<Log>(time_axis(time));
  for (const auto& [key, value] : columns) {
    const std::string name = text_argument(key, "columns");
    if (name.empty() || log->has(name)) {
      throw core::InputError(
          {{}, {}, {}, "columns"},
          name.empty() ? "a column without a name" : "column '" + name + "' twice",
          "give each column a name of its own");
    }
    const std::string unit = units.contains(key) ? text_argument(units[key], "units") : "";
    log->add_channel(name, unit, numbers(value, log->size(), name));
  }
  return log;
}

void bind_log_class(py::module_& m) {
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
      .def_property_readonly("channels", &Log::channel_names, "The channel names, in order.")
      .def(
          "unit", [](const Log& log, const std::string& name) { return log.channel(name).unit; },
          "The SI unit of a channel ('' dimensionless).");
}

void bind_source(py::module_& m) {
  using analysis::LogSource;
  py::class_<LogSource>(m, "LogSource")
      .def(py::init<>())
      .def_readwrite("log", &LogSource::log)
      .def_readwrite("map", &LogSource::map_file)
      .def_readwrite("col", &LogSource::columns)
      .def_readwrite("unit", &LogSource::units)
      .def_readwrite("clock_offset", &LogSource::clock_offsets)
      .def_readwrite("max_gap", &LogSource::max_gap_s)
      .def_readwrite("format", &LogSource::format)
      .def_readwrite("bag_time", &LogSource::bag_time)
      .def_readwrite("msg_path", &LogSource::msg_path)
      .def_readwrite("strict", &LogSource::strict)
      .def_readwrite("time_format", &LogSource::time_format)
      .def_readwrite("date", &LogSource::date)
      .def_readwrite("time_order", &LogSource::time_order)
      .def_readwrite("jobs", &LogSource::jobs)
      .def_property(
          "memory", [](const LogSource& s) { return std::const_pointer_cast<Log>(s.memory); },
          [](LogSource& s, std::shared_ptr<Log> log) { s.memory = std::move(log); });
  m.def(
      "read_log",
      [](const LogSource& source, std::optional<std::vector<std::string>> roles) {
        analysis::LoadedLog loaded;
        {
          py::gil_scoped_release release;
          loaded = source.load([&roles](const std::string& r) {
            return !roles || std::find(roles->begin(), roles->end(), r) != roles->end();
          });
        }
        auto log = std::make_shared<Log>(std::move(loaded.log));
        return py::make_tuple(log, io::to_json(loaded.input).dump());
      },
      py::arg("source"), py::arg("roles") = py::none());
  // Every numeric column of a CSV such as the simulator's truth.csv, named by its header, known
  // units in SI: the columns that are no role of a log too.
  m.def("read_csv_all", [](const std::filesystem::path& path) {
    std::shared_ptr<Log> log;
    {
      py::gil_scoped_release release;
      log = std::make_shared<Log>(io::read_csv_all(path));
    }
    return log;
  });
}

}  // namespace

void bind_log(py::module_& m) {
  bind_log_class(m);
  bind_source(m);
}

}  // namespace dynpos::python
