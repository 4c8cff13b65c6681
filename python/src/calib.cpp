// Lever-arm calibration (thesis chapter 4): GNSS antennas and MRUs. The requests' typed fields
// take Python values: vectors as sequences of three numbers (tuple, list, numpy array; or the
// text "X,Y,Z"), enums by name (the library's lookups, as the CLI), per-antenna inputs as dicts; a
// bad value raises InputError naming the keyword. The run functions write the outputs as the CLI
// does and return the JSON.

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <pybind11/eigen.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "bind.hpp"
#include "dynpos/analysis/leverarm_gnss.hpp"
#include "dynpos/analysis/leverarm_mru.hpp"
#include "dynpos/analysis/options.hpp"

namespace dynpos::python {
namespace {

using namespace dynpos::analysis;
using Vec3 = Eigen::Vector3d;

// A vector keyword: three finite numbers, else the error the CLI gives for the same text.
Vec3 vec3_of(const py::handle& value, const char* key, const char* example) {
  if (py::isinstance<py::str>(value)) return parse_vec3(value.cast<std::string>(), key, example);
  std::string text;
  try {
    const auto x = value.cast<std::vector<double>>();
    if (x.size() == 3 && std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); }))
      return {x[0], x[1], x[2]};
    text = fmt::format("{}", fmt::join(x, ","));
  } catch (const py::cast_error&) {
    text = py::str(value).cast<std::string>();
  }
  return parse_vec3(text, key, example);  // throws: not three finite numbers
}

std::optional<Vec3> optional_vec3(const py::handle& value, const char* key, const char* example) {
  if (value.is_none()) return std::nullopt;
  return vec3_of(value, key, example);
}

py::object vec3_or_none(const std::optional<Vec3>& v) { return v ? py::cast(*v) : py::none(); }

// The "X,Y,Z" examples of the CLI's hints.
const char* const kGain = "0.02,0.02,20";
const char* const kImuArm = "0.358,0.804,-4.321";

template <class Q>
void accel_property(py::class_<Q>& c) {
  c.def_property(
      "accel", [](const Q& q) { return std::string(calib::to_string(q.accel)); },
      [](Q& q, const std::string& name) { q.accel = accel_from_name(name); });
}

// A Vector3d option of LeverarmGnssRequest as a property taking Python values.
#define DYNPOS_VEC3_PROPERTY(FIELD, EXAMPLE)                    \
  def_property(                                                 \
      #FIELD, [](const Q& q) { return vec3_or_none(q.FIELD); }, \
      [](Q& q, const py::object& v) { q.FIELD = optional_vec3(v, #FIELD, EXAMPLE); })

void bind_leverarm_gnss(py::module_& m) {
  using Q = LeverarmGnssRequest;
  py::class_<Q> c(m, "LeverarmGnssRequest");
  c.def(py::init<>())
      .def_readwrite("source", &Q::source)
      .def_property(
          "method", [](const Q& q) { return std::string(to_string(q.method)); },
          [](Q& q, const std::string& name) { q.method = gnss_method_from_name(name); })
      .def_readwrite("imu", &Q::imu)
      .DYNPOS_VEC3_PROPERTY(imu_arm, kImuArm)
      .def_readwrite("antennas", &Q::antennas)
      .def_readwrite("gnss_log", &Q::gnss_log)
      .def_readwrite("nmea", &Q::nmea)
      .def_property(
          "utc_at_zero", [](const Q& q) { return q.utc_at_zero; },
          [](Q& q, const py::object& v) {
            if (v.is_none())
              q.utc_at_zero.reset();
            else if (py::isinstance<py::str>(v))
              q.utc_at_zero = parse_utc_at_zero(v.cast<std::string>());
            else
              q.utc_at_zero = v.cast<double>();
          })
      .def_property(
          "init", [](const Q& q) { return q.init; },
          [](Q& q, const std::map<std::string, py::object>& arms) {
            q.init.clear();
            for (const auto& [antenna, arm] : arms) q.init[antenna] = vec3_of(arm, "init", kGain);
          })
      .DYNPOS_VEC3_PROPERTY(w1, kGain)
      .DYNPOS_VEC3_PROPERTY(w2, kGain)
      .DYNPOS_VEC3_PROPERTY(gamma, kGain)
      .DYNPOS_VEC3_PROPERTY(L, kGain)
      .DYNPOS_VEC3_PROPERTY(init_p0, kGain)
      .def_readwrite("adaptive_rate", &Q::adaptive_rate)
      .def_readwrite("lag", &Q::lag)
      .def_readwrite("time_offset", &Q::time_offset)
      .def_readwrite("estimate_time_offset", &Q::estimate_time_offset)
      .def_readwrite("max_time_offset", &Q::max_time_offset)
      .def_readwrite("converged_from", &Q::converged_from)
      .def_readwrite("pe_window", &Q::pe_window)
      .def_readwrite("gnss_std", &Q::gnss_std);
  accel_property(c);
  m.def(
      "run_leverarm_gnss",
      [](const Q& q, const std::string& json, const std::string& plots) {
        q.validate();
        const Outputs outputs{json, plots};
        outputs.check("plots", true);
        return run_and_write(q, outputs, run_leverarm_gnss);
      },
      py::arg("request"), py::arg("json") = "", py::arg("plots") = "");
}

#undef DYNPOS_VEC3_PROPERTY

void bind_leverarm_mru(py::module_& m) {
  using Q = LeverarmMruRequest;
  py::class_<Q> c(m, "LeverarmMruRequest");
  c.def(py::init<>())
      .def_readwrite("source", &Q::source)
      .def_readwrite("mru_log", &Q::mru_log)
      .def_readwrite("reference", &Q::reference)
      .def_property(
          "method", [](const Q& q) { return std::string(calib::to_string(q.method)); },
          [](Q& q, const std::string& name) { q.method = mru_method_from_name(name); })
      .def_readwrite("window_s", &Q::window_s)
      .def_readwrite("tau_s", &Q::tau_s)
      .def_readwrite("w1", &Q::w1);
  accel_property(c);
  m.def(
      "run_leverarm_mru",
      [](const Q& q, const std::string& json, const std::string& plots) {
        q.validate();
        const Outputs outputs{json, plots};
        outputs.check("plots", true);
        return run_and_write(q, outputs, run_leverarm_mru);
      },
      py::arg("request"), py::arg("json") = "", py::arg("plots") = "");
}

// "X,Y[,Z]" as numbers; a piece that is not one number makes it no vector (empty).
std::vector<double> numbers_of(const std::string& text) {
  std::vector<double> out;
  std::size_t begin = 0;
  while (begin <= text.size()) {
    const std::size_t comma = std::min(text.find(',', begin), text.size());
    const std::string piece = text.substr(begin, comma - begin);
    char* end = nullptr;
    const double v = std::strtod(piece.c_str(), &end);
    if (end == piece.c_str() || std::string_view(end).find_first_not_of(" \t") != std::string::npos)
      return {};
    out.push_back(v);
    begin = comma + 1;
  }
  return out;
}

}  // namespace

std::optional<Vec3> antenna_arm(const py::handle& value, const char* key) {
  if (value.is_none()) return std::nullopt;
  std::vector<double> x;
  std::string text;
  if (py::isinstance<py::str>(value)) {
    text = value.cast<std::string>();
    x = numbers_of(text);
  } else {
    try {
      x = value.cast<std::vector<double>>();
      text = fmt::format("{}", fmt::join(x, ","));
    } catch (const py::cast_error&) {
      text = py::str(value).cast<std::string>();
    }
  }
  if (x.size() != 2 && x.size() != 3) {
    throw option_error(key, "'" + text + "' is not a lever arm of 2 or 3 numbers",
                       "give (X, Y) or (X, Y, Z) in metres (BODY: forward, starboard, down)");
  }
  return Vec3(x[0], x[1], x.size() > 2 ? x[2] : 0.0);
}

py::object arm_or_none(const std::optional<Vec3>& arm) { return vec3_or_none(arm); }

void bind_calib(py::module_& m) {
  bind_leverarm_gnss(m);
  bind_leverarm_mru(m);
}

}  // namespace dynpos::python
