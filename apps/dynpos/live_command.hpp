#pragma once
// dynpos live ANALYSIS: the stream options every live analysis shares, and the end of an
// analysis subcommand in either mode (for a stream: the session, then the final report's
// outputs). The session is live/session.hpp.

#include <CLI/CLI.hpp>
#include <cstdio>
#include <functional>
#include <memory>
#include <type_traits>

#include "commands.hpp"
#include "dynpos/analysis/log_source.hpp"
#include "dynpos/analysis/outputs.hpp"
#include "dynpos/live/session.hpp"

namespace dynpos::cli {

/// The options of `dynpos live` as the command line gives them.
struct LiveCli {
  live::LiveRequest request;
  int page_port = -1;  ///< --page-port; -1: no page
};

/// Adds --udp, --tcp, --follow, --idle-exit, --page-port, --update and --capture to `sub`, and
/// its live footer.
void add_live_options(CLI::App& sub, LiveCli& live, const std::string& example);

/// The request of `live` checked as the command line gives it: the JSON file not standard
/// output (that carries the JSON lines), the page's port.
live::LiveRequest live_request(const LiveCli& live, const analysis::LogSource& source,
                               const analysis::Outputs& outputs);

/// Runs the session (live::run_live on stdout and stderr) with Ctrl-C, SIGTERM and SIGHUP
/// ending it as the end of the stream would (live_session_takes_signal), and prints its
/// summary.
void run_live_session(const live::LiveRequest& request, const analysis::LogSource& source,
                      const live::LiveAnalysis& analysis);

/// The end of a live analysis subcommand: the session, each run by `run` on the data so far;
/// after the final run the report's outputs are written (write_outputs: the same files as the
/// offline command) and its text and the files written are printed on standard error.
template <class Report>
void run_live_command(const LiveCli& live, const analysis::LogSource& source,
                      const std::function<Report(const analysis::LogSource&)>& run,
                      const analysis::Outputs& outputs) {
  const live::LiveRequest request = live_request(live, source, outputs);
  const auto analyse = [&](const analysis::LogSource& data, bool final) {
    const Report report = run(data);
    if (final) print_report(stderr, report, write_outputs(report, outputs));
    return to_json(report);
  };
  run_live_session(request, source, analyse);
}

/// The callback of an analysis subcommand that reads a log in `mode`, its request made by
/// `request()` when the command runs: for LOG, write_and_print(run(request)); for a stream, the
/// stream options (`live_example` ends their footer) and run_live_command, each run on the
/// request with the data so far as its source. `request` owns (shares) the options `outputs`
/// is part of.
template <class Request, class Report>
void set_run_callback(CLI::App& sub, LogMode mode,
                      std::type_identity_t<std::function<Request()>> request,
                      Report (*run)(const Request&), const analysis::Outputs& outputs,
                      const std::string& live_example = {}) {
  if (mode == LogMode::kFile) {
    sub.callback([=, &outputs] { write_and_print(run(request()), outputs); });
    return;
  }
  auto live = std::make_shared<LiveCli>();
  add_live_options(sub, *live, live_example);
  sub.callback([=, &outputs] {
    const Request base = request();
    run_live_command<Report>(
        *live, base.source,
        [&](const analysis::LogSource& data) {
          Request q = base;
          q.source = data;
          return run(q);
        },
        outputs);
  });
}

}  // namespace dynpos::cli
