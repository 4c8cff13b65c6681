#include "dynpos/analysis/leverarm_mru.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <cmath>

#include "dynpos/analysis/options.hpp"
#include "dynpos/calib/imu_mru_arms.hpp"
#include "dynpos/core/error.hpp"
#include "leverarm_mru_roles.hpp"

namespace dynpos::analysis {
namespace {

// A name as the lookups compare it: options are taken in any case.
std::string lower_case(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

using detail::is_mru_accel_role;
using detail::mru_names;

bool wanted_role(const std::string& role) {
  for (const char* r : {"roll", "pitch", "heading", "p", "q", "r", "u", "v", "w"}) {
    if (role == r) return true;
  }
  return is_mru_accel_role(role);
}

// One MRU's accelerations in a file of its own.
struct MruFile {
  std::string name, file;
  core::Log log;
  io::InputReport input;
};

// The files of mru_log, each read with its own role mapping NAME.ax/ay/az by header name.
std::vector<MruFile> read_mru_files(const LeverarmMruRequest& q) {
  std::vector<MruFile> out;
  for (const auto& [name, file] : q.mru_log) {
    LogSource in = q.source;
    in.log = file;
    LoadedLog loaded = in.load([name](const std::string& role) {
      return role == name + ".ax" || role == name + ".ay" || role == name + ".az";
    });
    out.push_back({name, in.log.string(), std::move(loaded.log), std::move(loaded.input)});
  }
  return out;
}

calib::MruEstimateOptions estimate_options(const LeverarmMruRequest& q) {
  calib::MruEstimateOptions eo;
  eo.method = q.method;
  eo.tau_s = q.tau_s;
  eo.w1_per_s = q.w1;
  return eo;
}

// The arms of the log's other MRUs from the reference MRU, whose accelerations stand in for a₀:
// its roll, pitch, rates and accelerations and the heading are read, no velocity.
LeverarmMruReport run_from_reference(const LeverarmMruRequest& q) {
  const std::string& ref = q.reference;
  LoadedLog loaded = q.source.load([&ref](const std::string& role) {
    if (role == "heading" || is_mru_accel_role(role)) return true;
    for (const char* c : {".roll", ".pitch", ".p", ".q", ".r"}) {
      if (role == ref + c) return true;
    }
    return false;
  });
  const core::Log& log = loaded.log;
  std::vector<std::string> others;
  for (const std::string& name : mru_names(log)) {
    if (name != ref) others.push_back(name);
  }
  if (others.empty()) {
    throw q.source.error(ref + ".ax", "no MRU accelerations other than the reference " + ref + "'s",
                         "log a second MRU (mruK.ax, mruK.ay, mruK.az) to measure from " + ref);
  }
  LeverarmMruReport report;
  try {
    const calib::ImuSeries imu = calib::imu_from_log(log, ref, q.accel);
    report.result =
        calib::estimate_mru_arms_from_imu(imu, log, others, q.window_s, estimate_options(q));
    report.notes = imu.notes;
  } catch (const core::InputError& e) {
    throw q.source.in_log(e);
  }
  if (report.result.status != core::Status::kOk) {
    throw q.source.error("time", report.result.message,
                         "log a longer maneuver with rotation (a turning circle in waves)");
  }
  report.notes.push_back(fmt::format(
      "arms from {0}: its accelerations stand in for the origin's (a_k − a_{0} = M·(l_k − "
      "l_{0})), so no velocity is read; add {0}'s arm from the control origin for arms from it",
      ref));
  report.log = q.source.log;
  report.reference = ref;
  report.input = std::move(loaded.input);
  return report;
}

}  // namespace

calib::MruAccel accel_from_name(const std::string& name) {
  if (const auto a = calib::parse_mru_accel(lower_case(name))) return *a;
  throw option_error("accel", "unknown acceleration convention '" + name + "'",
                     "use kinematic or specific-force");
}

calib::MruMethod mru_method_from_name(const std::string& name) {
  if (const auto m = calib::parse_mru_method(lower_case(name))) return *m;
  throw option_error("method", "unknown method '" + name + "'", "use lsq or observer");
}

void LeverarmMruRequest::validate() const {
  // The smoother's window is a count of samples: bounded so that it is one at any log rate.
  if (!(window_s > 0.0 && window_s <= 600.0)) {
    throw option_error("window_s", fmt::format("{} s is not a window in (0, 600] s", window_s),
                       "about 1 s suits a 100 Hz MRU");
  }
  if (!(tau_s > 0.0 && tau_s <= 3600.0)) {
    throw option_error("tau_s", fmt::format("{} s is not a time constant in (0, 3600] s", tau_s),
                       "the default is 5 s");
  }
  if (!(w1 > 0.0) || !std::isfinite(w1)) {
    throw option_error("w1", fmt::format("{} is not a gain W₁ > 0 [1/s]", w1),
                       "the default is 0.01");
  }
  if (!reference.empty()) {
    const bool mru_name = reference.size() > 3 && reference.rfind("mru", 0) == 0 &&
                          std::all_of(reference.begin() + 3, reference.end(), [](char c) {
                            return std::isdigit(static_cast<unsigned char>(c));
                          });
    if (!mru_name) {
      throw option_error("reference", "'" + reference + "' is not an MRU role prefix",
                         "MRUs are named mruK, e.g. mru1");
    }
    if (!mru_log.empty()) {
      throw option_error("reference", "a reference MRU takes the MRUs of the log only",
                         "map the other MRU's columns with --col mruK.ax=COLUMN@FILE instead of "
                         "--mru-log");
    }
  }
  for (const auto& [name, file] : mru_log) {
    if (name.empty() || file.empty()) {
      throw option_error("mru_log", "malformed argument '" + name + "=" + file.string() + "'",
                         "expected NAME=FILE, e.g. --mru-log mru1=mru1.csv");
    }
  }
}

LeverarmMruReport run_leverarm_mru(const LeverarmMruRequest& q) {
  q.validate();
  if (!q.reference.empty()) return run_from_reference(q);
  LoadedLog loaded = q.source.load(wanted_role);
  const core::Log& motion = loaded.log;
  const std::vector<MruFile> files = read_mru_files(q);
  std::vector<calib::MruSource> sources;
  for (const MruFile& e : files) {
    sources.push_back({e.name, &e.log, e.file});
    loaded.input.append(e.input);
  }
  for (const std::string& name : mru_names(motion)) {
    bool dup = false;
    for (const auto& s : sources) dup = dup || s.name == name;
    if (!dup) sources.push_back({name, &motion, q.source.log.string()});
  }
  calib::MruSignalOptions so;
  so.accel = q.accel;
  so.smooth_window_s = q.window_s;
  calib::MruSignals signals;
  try {
    signals = calib::mru_signals_from_logs(motion, sources, so);
  } catch (const core::InputError& e) {
    throw q.source.in_log(e);
  }
  LeverarmMruReport report;
  report.log = q.source.log;
  report.input = std::move(loaded.input);
  report.result = calib::estimate_mru_arms(signals, estimate_options(q));
  if (report.result.status != core::Status::kOk) {
    throw q.source.error("time", report.result.message,
                         "log a longer maneuver with rotation (a turning circle in waves)");
  }
  report.notes = signals.notes;
  return report;
}

}  // namespace dynpos::analysis
