// dynpos identify station-keeping: pure-DP statistics over a window or per setpoint hold
// (thesis tables 3.11-3.22).

#include <memory>

#include "commands.hpp"
#include "dynpos/analysis/station_keeping.hpp"
#include "live_command.hpp"
#include "log_input.hpp"

namespace dynpos::cli {
namespace {

struct StationKeepingOptions {
  LogInput input;
  analysis::StationKeepingRequest request;
  analysis::Outputs outputs;
};

void run(StationKeepingOptions& o) {
  o.request.source = o.input;
  write_and_print(analysis::run_station_keeping(o.request), o.outputs);
}

// The end of `live identify station-keeping`: the session, each run on the data so far (the
// window, the last --duration seconds, moves with the stream).
void run_live_station_keeping(const StationKeepingOptions& o, const LiveCli& live) {
  run_live_command<analysis::StationKeepingReport>(
      live, o.input,
      [&o](const analysis::LogSource& data) {
        analysis::StationKeepingRequest request = o.request;
        request.source = data;
        return analysis::run_station_keeping(request);
      },
      o.outputs);
}

}  // namespace

void add_identify_station_keeping(CLI::App& identify, LogMode mode) {
  auto o = std::make_shared<StationKeepingOptions>();
  analysis::StationKeepingRequest& r = o->request;
  CLI::App* sub = identify.add_subcommand("station-keeping",
                                          "Pure DP: position, heading, wind and thrust statistics");
  o->input.add_options(*sub,
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
  if (mode == LogMode::kLive) {
    auto live = std::make_shared<LiveCli>();
    add_live_options(*sub, *live,
                     "dynpos live identify station-keeping --udp 0.0.0.0:10110 --duration 300 "
                     "--capture trial.nmea");
    sub->callback([o, live] { run_live_station_keeping(*o, *live); });
    return;
  }
  sub->callback([o] { run(*o); });
}

}  // namespace dynpos::cli
