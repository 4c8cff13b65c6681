#include "dynpos/analysis/leverarm_gnss.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <sstream>
#include <utility>

#include "dynpos/analysis/options.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/io/nmea.hpp"
#include "dynpos/io/nmea_log.hpp"
#include "dynpos/io/time_stamp.hpp"
#include "gnss_antenna_name.hpp"
#include "gps_week_rollover.hpp"
#include "leverarm_ins.hpp"

namespace dynpos::analysis {
namespace {

using Vec3 = Eigen::Vector3d;

bool motion_role(const std::string& role) {
  for (const char* r : {"roll", "pitch", "heading", "p", "q", "r", "u", "v", "w"})
    if (role == r) return true;
  return false;
}

bool gnss_role(const std::string& role) { return role.rfind("gnss", 0) == 0; }

bool mru_role(const std::string& role) { return role.rfind("mru", 0) == 0; }

// A name as the lookups compare it: options are taken in any case.
std::string lower_case(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

// The example of an X,Y,Z option in its error's hint (gains, initial arms and P₀ alike).
const char* const kGainExample = "0.02,0.02,20";

calib::GnssArmMethod thesis_method(LeverarmGnssMethod m) {
  switch (m) {
    case LeverarmGnssMethod::kLuenberger:
      return calib::GnssArmMethod::kLuenberger;
    case LeverarmGnssMethod::kAdaptive:
      return calib::GnssArmMethod::kAdaptive;
    default:
      return calib::GnssArmMethod::kLsq;
  }
}

void check_prefix(const std::string& p, const std::string& key) {
  if (!is_gnss_antenna_name(p))
    throw option_error(key, "'" + p + "' is not an antenna role prefix",
                       "antennas are named gnssK, e.g. gnss1");
}

// The per-antenna input files: an antenna name and an existing file each.
void check_antenna_files(const std::map<std::string, std::filesystem::path>& files,
                         const std::string& key, const std::string& what) {
  for (const auto& [prefix, file] : files) {
    check_prefix(prefix, key);
    if (!std::filesystem::exists(file))
      throw option_error_in_file(file, key, "file not found", "give an existing " + what);
  }
}

// A vector option given from a program (not parsed from text) must still be finite.
void check_finite(const Vec3& v, const std::string& key) {
  if (!v.allFinite())
    throw option_error(key, "the vector must be three finite numbers",
                       "for example " + std::string(kGainExample));
}

// The estimator's options from the request, every option but the initial arms (which need the
// antennas of the data) checked in the command line's order.
calib::GnssArmOptions arm_options(const LeverarmGnssRequest& q) {
  calib::GnssArmOptions lo;
  lo.method = thesis_method(q.method);
  if (q.w1) lo.luenberger_w_p0 = *q.w1;
  if (q.w2) lo.luenberger_w_arm = *q.w2;
  if (q.gamma) lo.adaptive_gamma = *q.gamma;
  if (q.L) lo.adaptive_l = *q.L;
  auto positive = [](const Vec3& v, const char* key) {
    if (!(v.array() > 0.0).all() || !v.allFinite())
      throw option_error(key, "gains must be > 0", "for example 0.02,0.02,20");
  };
  positive(lo.luenberger_w_p0, "w1");
  positive(lo.luenberger_w_arm, "w2");
  if (lo.adaptive_gamma) positive(*lo.adaptive_gamma, "gamma");
  positive(lo.adaptive_l, "L");
  if (!(q.adaptive_rate > 0.0) || !std::isfinite(q.adaptive_rate))
    throw option_error("adaptive_rate", "the rate must be > 0", "for example 0.1 [1/s]");
  lo.adaptive_rate_per_s = q.adaptive_rate;
  if (q.init_p0) check_finite(*q.init_p0, "init_p0");
  lo.initial_p0_n_m = q.init_p0;
  for (const auto& [antenna, arm] : q.init) check_finite(arm, "init");
  if (q.lag < 1) throw option_error("lag", "the lag must be >= 1 epoch");
  lo.lag_epochs = q.lag;
  if (q.time_offset && q.estimate_time_offset)
    throw option_error("time_offset", "--time-offset and --estimate-time-offset exclude each other",
                       "give one of them");
  if (q.time_offset) {
    if (!std::isfinite(*q.time_offset))
      throw option_error("time_offset", "the offset must be finite");
    lo.time_offset_s = *q.time_offset;
  }
  lo.estimate_time_offset = q.estimate_time_offset;
  // The search steps through the range: 60 s covers any receiver's latency or a wrong clock
  // second, and keeps the search bounded.
  if (!(q.max_time_offset >= 0.05 && q.max_time_offset <= 60.0))
    throw option_error("max_time_offset", "must be in [0.05, 60] s",
                       "a GNSS latency is well below a second; 1 s is the default");
  lo.max_time_offset_s = q.max_time_offset;
  if (!(q.converged_from >= 0.0 && q.converged_from < 1.0))
    throw option_error("converged_from", "must be in [0, 1)",
                       "0.5 averages over the second half of the log");
  lo.converged_from_fraction = q.converged_from;
  if (!(q.pe_window > 0.0) || !std::isfinite(q.pe_window))
    throw option_error("pe_window", "must be > 0 s");
  lo.excitation.window_s = q.pe_window;
  if (!(q.gnss_std > 0.0) || !std::isfinite(q.gnss_std))
    throw option_error("gnss_std", "must be > 0 m");
  lo.excitation.gnss_std_m = q.gnss_std;
  return lo;
}

// The initial arms of `init` in the order of the estimated antennas `names`.
std::vector<Vec3> initial_arms(const std::map<std::string, Vec3>& init,
                               const std::vector<std::string>& names) {
  if (init.empty()) return {};
  std::vector<Vec3> arms(names.size(), Vec3::Zero());
  for (const auto& [p, v] : init) {
    const auto it = std::find(names.begin(), names.end(), p);
    if (it == names.end())
      throw option_error("init", "antenna '" + p + "' is not estimated",
                         "the antennas are the gnssK of the inputs (or --antennas)");
    arms[static_cast<std::size_t>(it - names.begin())] = v;
  }
  return arms;
}

// The motion log, the per-antenna logs of gnss_log and nmea, and where each antenna's fixes are
// (pointers into the logs: an Inputs is not copied or moved once filled).
struct Inputs {
  core::Log log;
  io::InputReport input;
  std::vector<core::Log> extra;  // kept alive for the GnssSource pointers
  std::vector<calib::GnssSource> sources;
  std::vector<std::string> notes;
};

// `log` with shift_s added to its times.
core::Log shifted_by(const core::Log& log, double shift_s) {
  std::vector<double> t = log.time();
  for (double& x : t) x += shift_s;
  core::Log out(std::move(t));
  for (const core::Channel& c : log.channels()) out.add_channel(c.name, c.unit, c.values, c.interp);
  return out;
}

// An NMEA file's fixes on the log's clock: NMEA time is UTC seconds of day, the log's t = 0 is
// at utc_at_zero; without it the NMEA times must overlap the log's (a log kept in UTC).
core::Log nmea_on_log_clock(const core::Log& nmea, const core::Log& motion,
                            const std::optional<double>& utc0, const std::string& file) {
  const std::vector<double>& t = nmea.time();
  const auto& mt = motion.time();
  if (!utc0) {
    const bool overlap = !t.empty() && t.back() >= mt.front() && t.front() <= mt.back();
    if (!overlap)
      throw option_error_in_file(
          file, "utc_at_zero",
          fmt::format("the NMEA times ({:.0f} … {:.0f} s UTC of day) do not overlap the log's "
                      "times ({:.0f} … {:.0f} s)",
                      t.front(), t.back(), mt.front(), mt.back()),
          "give the UTC time of the log's t = 0 with --utc-at-zero HH:MM:SS[.sss] (a virtual "
          "trial writes it as start_utc in truth.json)");
  }
  return shifted_by(nmea, utc0 ? -*utc0 : 0.0);
}

// An antenna's NMEA file — a serial capture with logger stamps and cut lines is fine — on the
// log's clock: by the difference of the absolute times when both the log (date-time stamps)
// and the capture (a date from RMC or the logger) have one; else as UTC seconds of day, placed
// by utc_at_zero or overlapping the log's times (nmea_on_log_clock).
core::Log read_antenna_capture(const LeverarmGnssRequest& q, const std::string& prefix,
                               const std::string& file, Inputs& in,
                               const std::optional<double>& utc0) {
  io::NmeaLogOptions o;
  o.prefix = prefix;
  o.strict = q.source.strict;
  o.wanted = [&prefix](const std::string& c) {
    return c == prefix + ".lat" || c == prefix + ".lon" || c == prefix + ".height";
  };
  io::NmeaLog nl = io::read_nmea_log(file, o);
  in.notes.push_back(fmt::format("{}: {} NMEA sentences from {} ({} lines skipped)", prefix,
                                 nl.report.records, file, nl.report.skipped.total()));
  std::optional<io::ParsedStamp> main0;
  if (in.input.origin) main0 = io::parse_iso8601(*in.input.origin);
  core::Log placed;
  if (nl.origin_ns && main0 && !utc0) {
    const int cycles = detail::gps_week_rollover_cycles(in.log, main0->ns, nl.log, *nl.origin_ns,
                                                        0.0, q.source.strict, nl.report);
    placed = shifted_by(nl.log, detail::origin_offset_s(main0->ns, *nl.origin_ns, cycles));
    nl.report.notes.push_back("aligned on the main log by its absolute time stamps");
  } else if (nl.origin_ns) {
    const std::int64_t day_ns = 86'400'000'000'000;
    const double t0 = 1e-9 * static_cast<double>(((*nl.origin_ns % day_ns) + day_ns) % day_ns);
    placed = nmea_on_log_clock(shifted_by(nl.log, t0), in.log, utc0, file);
  } else {  // no date anywhere: the times of day of GGA itself, by the plain-file reader

    placed = nmea_on_log_clock(io::read_nmea_gnss(file, prefix).log, in.log, utc0, file);
  }
  in.input.append(describe_input(placed, file, std::move(nl.report), q.source.jobs));
  return placed;
}

// The antennas: those asked for, else every gnssK of the log and the extra files, in K order.
std::vector<std::string> antenna_names(
    const LeverarmGnssRequest& q, const core::Log& log,
    const std::map<std::string, std::pair<std::size_t, std::string>>& external) {
  std::vector<std::string> prefixes = q.antennas;
  if (!prefixes.empty()) return prefixes;
  prefixes = calib::gnss_prefixes(log);
  for (const auto& [p, e] : external)
    if (std::find(prefixes.begin(), prefixes.end(), p) == prefixes.end()) prefixes.push_back(p);
  std::sort(prefixes.begin(), prefixes.end(), [](const std::string& a, const std::string& b) {
    return std::stoi(a.substr(4)) < std::stoi(b.substr(4));
  });
  return prefixes;
}

// Fills `in` in place: its sources point into it.
void read_inputs(const LeverarmGnssRequest& q, Inputs& in) {
  LoadedLog loaded = q.source.load(
      [](const std::string& r) { return motion_role(r) || gnss_role(r) || mru_role(r); });
  in.log = std::move(loaded.log);
  in.input = std::move(loaded.input);
  std::map<std::string, std::pair<std::size_t, std::string>> external;  // prefix → (extra, file)
  in.extra.reserve(q.gnss_log.size() + q.nmea.size());
  for (const auto& [prefix, path] : q.gnss_log) {
    const std::string file = path.string();
    LogSource li;
    li.log = file;
    li.map_file = q.source.map_file;
    for (const std::string& c : q.source.columns)
      if (c.rfind(prefix + ".", 0) == 0) li.columns.push_back(c);
    for (const std::string& u : q.source.units)
      if (u.rfind(prefix + ".", 0) == 0) li.units.push_back(u);
    const std::string dot = prefix + ".";
    LoadedLog extra = li.load([&dot](const std::string& r) { return r.rfind(dot, 0) == 0; });
    in.extra.push_back(std::move(extra.log));
    in.input.append(std::move(extra.input));
    external[prefix] = {in.extra.size() - 1, file};
  }
  for (const auto& [prefix, path] : q.nmea) {
    const std::string file = path.string();
    in.extra.push_back(read_antenna_capture(q, prefix, file, in, q.utc_at_zero));
    external[prefix] = {in.extra.size() - 1, file};
  }
  const std::vector<std::string> prefixes = antenna_names(q, in.log, external);
  if (prefixes.empty())
    throw q.source.error("gnss1.lat", "no GNSS antenna in the inputs",
                         "map gnssK.lat/lon/height or gnssK.north/east/down with --col, or give "
                         "--gnss-log gnssK=FILE or --nmea gnssK=FILE");
  for (const std::string& p : prefixes) {
    const auto it = external.find(p);
    if (it != external.end())
      in.sources.push_back({&in.extra[it->second.first], p, it->second.second});
    else
      in.sources.push_back({&in.log, p, q.source.log.string()});
  }
}

// The motion of the log; the library does not know the file, so it is put into its errors.
calib::MotionFromLog motion_of(const core::Log& log, const LogSource& source) {
  try {
    return calib::motion_from_mixed_log(log);
  } catch (const core::InputError& e) {
    throw source.in_log(e);
  }
}

// The GNSS rate for the predicted σ: the median fix spacing of the antenna (≥ 3 fixes).
double fix_rate_hz(const calib::GnssSeries& g) {
  std::vector<double> dt;
  for (std::size_t i = 1; i < g.t_s.size(); ++i) dt.push_back(g.t_s[i] - g.t_s[i - 1]);
  std::nth_element(dt.begin(), dt.begin() + static_cast<long>(dt.size() / 2), dt.end());
  return 1.0 / dt[dt.size() / 2];
}

// Method ins: the logger-only estimate.
LeverarmGnssReport run_ins_report(const LeverarmGnssRequest& q, Inputs& in) {
  const std::vector<calib::GnssSeries> gnss = calib::gnss_from_logs(in.sources);
  LeverarmGnssReport report;
  report.method = LeverarmGnssMethod::kIns;
  report.log = q.source.log;
  report.ins = detail::run_ins(q, in.log, gnss);
  report.input = std::move(in.input);
  report.gnss_rate_hz = fix_rate_hz(gnss[0]);
  report.input_notes = in.notes;
  return report;
}

}  // namespace

std::string_view to_string(LeverarmGnssMethod m) {
  switch (m) {
    case LeverarmGnssMethod::kAuto:
      return "auto";
    case LeverarmGnssMethod::kIns:
      return "ins";
    case LeverarmGnssMethod::kLuenberger:
      return "luenberger";
    case LeverarmGnssMethod::kAdaptive:
      return "adaptive";
    case LeverarmGnssMethod::kLsq:
      return "lsq";
  }
  return "lsq";
}

LeverarmGnssMethod gnss_method_from_name(const std::string& name) {
  for (const LeverarmGnssMethod m : kLeverarmGnssMethods)
    if (lower_case(name) == to_string(m)) return m;
  throw option_error("method", "unknown method '" + name + "'",
                     "use auto, ins, luenberger, adaptive or lsq");
}

double parse_utc_at_zero(const std::string& text) {
  try {
    return io::parse_utc_time_of_day(text);
  } catch (const core::InputError& e) {
    throw option_error("utc_at_zero", e.problem(), e.hint());
  }
}

void LeverarmGnssRequest::validate() const {
  check_antenna_files(gnss_log, "gnss_log", "CSV file");
  if (utc_at_zero && !(*utc_at_zero >= 0.0 && *utc_at_zero < 86'400.0))
    throw option_error("utc_at_zero", fmt::format("{} s is not a time of day", *utc_at_zero),
                       "give seconds of the UTC day in [0, 86400), or HH:MM:SS[.sss]");
  check_antenna_files(nmea, "nmea", "NMEA 0183 file");
  for (const std::string& p : antennas) check_prefix(p, "antennas");
  arm_options(*this);
  detail::validate_ins_options(*this);
}

LeverarmGnssReport run_leverarm_gnss(const LeverarmGnssRequest& q) {
  q.validate();
  Inputs in;
  read_inputs(q, in);
  const bool ins = q.method == LeverarmGnssMethod::kIns ||
                   (q.method == LeverarmGnssMethod::kAuto && detail::has_ins_inputs(in.log));
  if (ins) return run_ins_report(q, in);
  const calib::MotionFromLog motion = motion_of(in.log, q.source);
  const std::vector<calib::GnssSeries> gnss = calib::gnss_from_logs(in.sources);
  // Proposition 2's persistence of excitation is judged over windows of pe_window seconds: a
  // log shorter than one window cannot show it (and is too short for a calibration).
  const auto& mt = motion.motion.t_s;
  const double span = mt.back() - mt.front();
  if (span < q.pe_window)
    throw option_error_in_file(
        q.source.log.string(), "pe_window",
        fmt::format("the motion spans {:.1f} s, shorter than one excitation window of {:.0f} s",
                    span, q.pe_window),
        "log a maneuver of a few minutes with turning and roll (e.g. a turning circle), or "
        "shorten --pe-window");
  std::vector<std::string> names;
  for (const auto& g : gnss) names.push_back(g.name);
  calib::GnssArmOptions lo = arm_options(q);
  lo.initial_arms_b_m = initial_arms(q.init, names);
  LeverarmGnssReport report;
  report.method = q.method == LeverarmGnssMethod::kAuto ? LeverarmGnssMethod::kLsq : q.method;
  report.log = q.source.log;
  report.input = std::move(in.input);
  report.pe_window_s = q.pe_window;
  report.gnss_rate_hz = fix_rate_hz(gnss[0]);
  lo.excitation.gnss_rate_hz = report.gnss_rate_hz;
  report.result = calib::estimate_gnss_arms(motion.motion, gnss, lo);
  if (report.result.status != core::Status::kOk)
    throw q.source.error("time", report.result.message,
                         "check that the GNSS fixes and the motion cover the same time (a "
                         "maneuver of a few minutes with turning and roll)");
  report.input_notes = motion.notes;
  report.input_notes.insert(report.input_notes.end(), in.notes.begin(), in.notes.end());
  return report;
}

}  // namespace dynpos::analysis
