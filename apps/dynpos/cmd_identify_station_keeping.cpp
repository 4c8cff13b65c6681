// dynpos identify station-keeping: pure-DP statistics over a window or per setpoint hold
// (thesis tables 3.11-3.22).

#include <memory>

#include "commands.hpp"
#include "dynpos/analysis/station_keeping.hpp"
#include "live_command.hpp"
#include "log_input.hpp"

namespace dynpos::cli {

void add_identify_station_keeping(CLI::App& identify, LogMode mode) {
  auto o = std::make_shared<AnalysisOptions<analysis::StationKeepingRequest>>();
  analysis::StationKeepingRequest& r = o->request;
  CLI::App* sub = identify.add_subcommand("station-keeping",
                                          "Pure DP: position, heading, wind and thrust statistics");
  add_log_options(*sub, r.source,
                  "time, north, east (m, any offset) or lat, lon; heading, wind_speed, "
                  "wind_dir; thrust.NAME, power.NAME; setpoint.north/east/heading",
                  mode);
  sub->add_option("--from", r.t_from_s, "Window start [s]");
  sub->add_option("--to", r.t_to_s, "Window end [s]");
  sub->add_option("--duration", r.duration_s,
                  "Window length [s] when --from or --to is not given (default: the last 5 min "
                  "of the log, or of each setpoint hold)")
      ->capture_default_str();
  sub->add_flag("--per-setpoint", r.per_setpoint,
                "One window per DP setpoint hold: its last --duration seconds");
  sub->add_option("--waves", r.waves, "Waves as observed, printed and kept in the JSON");
  sub->add_option("--current", r.current, "Current as observed, printed and kept in the JSON");
  add_json_option(*sub, o->outputs.json, "Write the results as JSON to FILE, or '-' for stdout");
  sub->footer(
      "Position std about the window's mean [m]; heading and wind direction by circular "
      "statistics [deg]; mean |thrust| [kN] and energy ∫P dt [kJ] per thruster and total. A "
      "channel that is not logged is '—' / null. Example on a virtual trial log: dynpos identify "
      "station-keeping DIR/log.csv --col north=gnss1.north --col east=gnss1.east --per-setpoint");
  // Live: each run on the data so far (the window, the last --duration seconds, moves with the
  // stream).
  set_run_callback<analysis::StationKeepingRequest>(
      *sub, mode, [o] { return o->request; }, analysis::run_station_keeping, o->outputs,
      "dynpos live identify station-keeping --udp 0.0.0.0:10110 --duration 300 --capture "
      "trial.nmea");
}

}  // namespace dynpos::cli
