// dynpos live identify step|station-keeping, dynpos live leverarm gnss: the analyses on a
// stream as it arrives (live/session.hpp). The analyses' own options are registered by their
// files in live mode; this file holds the stream options and the parent commands.

#include <atomic>

#include "commands.hpp"
#include "dynpos/analysis/options.hpp"
#include "dynpos/core/error.hpp"
#include "live_command.hpp"

namespace dynpos::cli {
namespace {

// The one piece of process-wide state of dynpos live: whether a session runs and whether a
// signal asked it to end. The signal thread (main.cpp) sets it, the session's loop reads it
// through LiveRequest::stop; a signal reaches the process, not a session, hence a flag of the
// process. A lock-free atomic, so it would also do for a handler in the POSIX sense.
enum SessionState : int { kNoSession, kRunning, kStopAsked };
std::atomic<int> session_state{kNoSession};
static_assert(std::atomic<int>::is_always_lock_free);

// Marks a session running while it lives.
class RunningSession {
 public:
  RunningSession() { session_state.store(kRunning); }
  ~RunningSession() { session_state.store(kNoSession); }
  RunningSession(const RunningSession&) = delete;
  RunningSession& operator=(const RunningSession&) = delete;
};

// --json and --strict as they are live: a file only (standard output carries the lines), and
// what a bad line does to the session.
void describe_live_log_options(CLI::App& sub) {
  if (CLI::Option* json = sub.get_option_no_throw("--json")) {
    json->description(
        "Write the final result as JSON to FILE, as the offline command does (standard output "
        "carries the JSON lines, so not '-')");
    json->get_validator(0)->description("FILE");
  }
  if (CLI::Option* strict = sub.get_option_no_throw("--strict")) {
    strict->description(
        "A bad tag block ends the session with an error naming the stream and its line "
        "(without: the line is dropped and counted), and an NMEA line the analysis cannot use "
        "makes its runs an error (file:line), the final one included");
  }
}

}  // namespace

bool live_session_takes_signal() noexcept {
  int running = kRunning;
  return session_state.compare_exchange_strong(running, kStopAsked);
}

void run_live_session(const live::LiveRequest& request, const analysis::LogSource& source,
                      const live::LiveAnalysis& analysis) {
  live::LiveRequest r = request;
  r.stop = [] { return session_state.load() == kStopAsked; };
  const RunningSession running;
  print_text(stderr, live::summary_text(live::run_live(r, source, analysis, stdout, stderr)));
}

void add_live_options(CLI::App& sub, LiveCli& live, const std::string& example) {
  live::LiveRequest& r = live.request;
  CLI::Option* udp = sub.add_option("--udp", r.udp,
                                    "Listen for NMEA datagrams on HOST:PORT (plain, or IEC "
                                    "61162-450 with UdPbC header and tag blocks; a multicast "
                                    "group is joined; port 0: one the system picks, printed)");
  CLI::Option* tcp = sub.add_option("--tcp", r.tcp, "Read lines from the TCP server HOST:PORT");
  CLI::Option* follow =
      sub.add_option("--follow", r.follow,
                     "Read FILE (CSV or NMEA) from its start and then what is appended to it");
  udp->excludes(tcp)->excludes(follow);
  tcp->excludes(follow);
  describe_live_log_options(sub);
  sub.add_option("--idle-exit", r.idle_exit_s,
                 "End, with the final result, when nothing has arrived for SECONDS (without it, "
                 "a UDP port or a followed file is read until Ctrl-C, which also ends with the "
                 "final result)");
  sub.add_option("--page-port", live.page_port,
                 "Serve a page that shows the results as they come on http://127.0.0.1:PORT/ "
                 "(0: a port the system picks, printed); default: no page")
      ->check(CLI::Range(0, 65535));
  sub.add_option("--update", r.update_s,
                 "Stream time [s] between re-runs of the analysis, at least (more when a run "
                 "takes more than 5 % of that time of processor)")
      ->capture_default_str();
  output_file(sub.add_option("--capture", r.capture,
                             "Keep the lines read (tag blocks removed) in FILE: the offline "
                             "command on FILE gives the final result again"));
  sub.footer(
      sub.get_footer() +
      "\n\nLive: writes one JSON line per new result on standard output: the document of the "
      "offline "
      "--json, compact, with \"stream_time_s\" and \"final\" added at its end; the last line, "
      "\"final\": true, when the stream ends (a TCP server closes), nothing has arrived for "
      "--idle-exit seconds or Ctrl-C (SIGINT, SIGTERM) is pressed once, equals the offline "
      "analysis of the same data (a second Ctrl-C stops at once, exit 130). --json FILE writes "
      "that final document as the offline command does. Example: " +
      example);
}

live::LiveRequest live_request(const LiveCli& live, const analysis::LogSource& source,
                               const analysis::Outputs& outputs) {
  if (outputs.json == "-") {
    throw analysis::option_error("json", "standard output carries the live JSON lines",
                                 "give a file, e.g. --json final.json");
  }
  live::LiveRequest request = live.request;
  if (live.page_port >= 0) request.http_port = static_cast<std::uint16_t>(live.page_port);
  request.strict = source.strict;
  return request;
}

namespace {

const char* const kLiveAnalyses = "identify step, identify station-keeping or leverarm gnss";

// `group` takes one of its subcommands; a word that is none of them is an error naming
// ANALYSIS and the analyses there are (CLI11 alone would only say a subcommand is required).
void require_analysis(CLI::App& group, const std::string& path) {
  group.require_subcommand(0, 1);
  group.allow_extras();
  group.callback([&group, path] {
    if (!group.get_subcommands().empty()) return;
    const std::vector<std::string> rest = group.remaining();
    std::string given = path;
    if (!rest.empty()) given += (given.empty() ? "" : " ") + rest.front();
    throw core::InputError({},
                           given.empty() ? "no ANALYSIS given" : "unknown ANALYSIS '" + given + "'",
                           std::string("dynpos live takes ") + kLiveAnalyses);
  });
}

}  // namespace

void register_live(CLI::App& app) {
  CLI::App* live = app.add_subcommand(
      "live",
      "Live trial: an analysis on a stream as it arrives (UDP, TCP, a growing file), its "
      "results as JSON lines and on a local page");
  require_analysis(*live, "");
  CLI::App* identify =
      live->add_subcommand("identify", "identify step or station-keeping on a live stream");
  require_analysis(*identify, "identify");
  add_identify_step(*identify, LogMode::kLive);
  add_identify_station_keeping(*identify, LogMode::kLive);
  CLI::App* leverarm = live->add_subcommand("leverarm", "leverarm gnss on a live stream");
  require_analysis(*leverarm, "leverarm");
  add_leverarm_gnss(*leverarm, LogMode::kLive);
}

}  // namespace dynpos::cli
