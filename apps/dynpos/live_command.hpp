#pragma once
// dynpos live ANALYSIS: the stream options every live analysis shares, and the end of a live
// subcommand (the session, then the final report's outputs). The session is live/session.hpp.

#include <CLI/CLI.hpp>
#include <cstdio>
#include <functional>

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

/// Prints the session's summary on standard error.
void print_live_summary(const live::LiveSummary& summary);

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
    if (final) {
      const analysis::Written written = write_outputs(report, outputs);
      print_text(stderr, to_text(report));
      for (const auto& file : written) print_text(stderr, "wrote {}\n", file.string());
    }
    return to_json(report);
  };
  run_live_session(request, source, analyse);
}

}  // namespace dynpos::cli
