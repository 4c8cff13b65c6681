// The DP observer over a logged DP run (estimate) and the consequence analysis along it, with the
// CLI's option names. estimate also returns the observer's time series as a Log in SI.

#include <pybind11/eigen.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <array>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>

#include "bind.hpp"
#include "dynpos/analysis/consequence.hpp"
#include "dynpos/analysis/estimate.hpp"
#include "dynpos/analysis/options.hpp"
#include "dynpos/core/angle.hpp"
#include "dynpos/core/log.hpp"

namespace dynpos::python {
namespace {

using namespace dynpos::analysis;

// The options of the observer run, on EstimateRequest itself or on the one a ConsequenceRequest
// holds: `get(q)` is that EstimateRequest (const or not, as q).
template <class Q, class Get>
void observer_options(py::class_<Q>& c, Get get) {
  c.def_property(
       "source", [get](const Q& q) { return get(q).source; },
       [get](Q& q, const LogSource& s) { get(q).source = s; })
      .def_property(
          "vessel", [get](const Q& q) { return get(q).vessel; },
          [get](Q& q, const std::filesystem::path& v) { get(q).vessel = v; })
      .def_property(
          "arm", [get](const Q& q) { return arm_or_none(get(q).arm_m); },
          [get](Q& q, const py::object& v) { get(q).arm_m = antenna_arm(v, "arm"); })
      .def_property(
          "observer", [get](const Q& q) { return get(q).observer; },
          [get](Q& q, const std::string& name) { get(q).observer = name; })
      .def_property(
          "tp", [get](const Q& q) { return get(q).tp_s; },
          [get](Q& q, double v) { get(q).tp_s = v; })
      .def_property(
          "rate", [get](const Q& q) { return get(q).rate_hz; },
          [get](Q& q, double v) { get(q).rate_hz = v; })
      .def_property(
          "max_hold", [get](const Q& q) { return get(q).max_hold_s; },
          [get](Q& q, double v) { get(q).max_hold_s = v; })
      .def_property(
          "mru", [get](const Q& q) { return get(q).mru; },
          [get](Q& q, const std::string& name) { get(q).mru = name; })
      .def_property(
          "settle", [get](const Q& q) { return get(q).settle_s; },
          [get](Q& q, double v) { get(q).settle_s = v; })
      .def_property(
          "from_", [get](const Q& q) { return get(q).t_from_s; },
          [get](Q& q, std::optional<double> v) { get(q).t_from_s = v; })
      .def_property(
          "to", [get](const Q& q) { return get(q).t_to_s; },
          [get](Q& q, std::optional<double> v) { get(q).t_to_s = v; });
}

// The observer's track in SI, as truth.csv names the true low-frequency motion: lf.north,
// lf.east [m], lf.heading [rad, 0–2π), lf.u, lf.v [m/s], lf.r [rad/s], bias.north, bias.east [N],
// bias.yaw [N*m] (b̂ in NED), position.age [s], one row per observer step.
std::shared_ptr<core::Log> series_si(const control::ObserverTrack& track) {
  auto log = std::make_shared<core::Log>();
  const std::pair<const char*, const char*> columns[] = {
      {"lf.north", "m"},   {"lf.east", "m"},     {"lf.heading", "rad"}, {"lf.u", "m/s"},
      {"lf.v", "m/s"},     {"lf.r", "rad/s"},    {"bias.north", "N"},   {"bias.east", "N"},
      {"bias.yaw", "N*m"}, {"position.age", "s"}};
  for (const auto& [name, unit] : columns) log->declare_channel(name, unit);
  log->reserve(track.t_s.size());
  for (std::size_t k = 0; k < track.t_s.size(); ++k) {
    const control::ObserverEstimate& e = track.estimate[k];
    const std::array<double, 10> row = {e.eta_n.x(),
                                        e.eta_n.y(),
                                        core::wrap_2pi(e.eta_n.z()),
                                        e.nu_b.x(),
                                        e.nu_b.y(),
                                        e.nu_b.z(),
                                        e.bias_n.x(),
                                        e.bias_n.y(),
                                        e.bias_n.z(),
                                        track.position_age_s.at(k)};
    log->append_row(track.t_s[k], row);
  }
  return log;
}

void bind_estimate_request(py::module_& m) {
  using Q = EstimateRequest;
  py::class_<Q> c(m, "EstimateRequest");
  c.def(py::init<>()).def_readwrite("out", &Q::out);
  observer_options(
      c, [](auto& q) -> auto& { return q; });
  // (the --json text, the series in SI)
  m.def(
      "run_estimate",
      [](Q q, const std::string& json, const std::string& out) {
        q.out = out;
        const Outputs outputs{.json = json, .figures = {}};
        outputs.check("plots", true);
        check_output_file("out", out);
        py::gil_scoped_release release;
        const EstimateReport report = run_estimate(q);
        write_outputs(report, outputs);
        return std::pair(to_json(report).dump(), series_si(report.track));
      },
      py::arg("request"), py::arg("json") = "", py::arg("out") = "");
}

void bind_consequence(py::module_& m) {
  using Q = ConsequenceRequest;
  py::class_<Q> c(m, "ConsequenceRequest");
  c.def(py::init<>())
      .def_readwrite("step", &Q::step_s)
      .def_readwrite("window", &Q::mean_window_s)
      .def_readwrite("out", &Q::out);
  observer_options(
      c, [](auto& q) -> auto& { return q.estimate; });
  m.def(
      "run_consequence",
      [](Q q, const std::string& json, const std::string& out) {
        q.out = out;
        const Outputs outputs{.json = json, .figures = {}};
        outputs.check("plots", true);
        check_output_file("out", out);
        return run_and_write(q, outputs, run_consequence);
      },
      py::arg("request"), py::arg("json") = "", py::arg("out") = "");
}

}  // namespace

void bind_estimate(py::module_& m) {
  bind_estimate_request(m);
  bind_consequence(m);
}

}  // namespace dynpos::python
