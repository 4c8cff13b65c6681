// dynpos: dynamic positioning toolkit — identification, lever-arm calibration, hybrid control
// and a virtual sea trial of R/V Gunnerus. This file only wires the subcommands together.

#include <fmt/core.h>

#include <pthread.h>

#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "commands.hpp"
#include "dynpos/analysis/error_report.hpp"
#include "dynpos/io/temporary_files.hpp"

namespace {

// Ctrl-C, SIGTERM and SIGHUP are blocked in every thread (the mask is inherited) and taken by
// one thread, which removes this run's temporary files (io/temporary_files.hpp) and ends the
// process with 128 + the signal's number, as a shell reports it. Outputs already renamed into
// place stay; none is left half-written. A run whose files are being renamed into place is
// let finish placing them first (temporary_files::Hold), so its files are all new or all old.
// The thread gets a small stack (it only waits and removes files), so it starts even under a
// tight memory limit (`ulimit -v`); if the system cannot start it at all, the signals are
// unblocked again and end the process as they would any program (temporary files then stay).
// A live session (dynpos live) takes the first signal as the end of its stream: it writes its
// final result and the command ends as usual; a second signal ends the process.
void* take_signals(void* signals) {
  int signal = 0;
  for (;;) {
    if (sigwait(static_cast<const sigset_t*>(signals), &signal) != 0) return nullptr;
    if (!dynpos::cli::live_session_takes_signal()) break;
    std::fprintf(stderr,
                 "dynpos live: signal %d: ending the session with its final result (again to "
                 "stop at once)\n",
                 signal);
  }
  const std::size_t removed = dynpos::io::temporary_files::remove_all_for_exit();
  std::fprintf(stderr, "dynpos: stopped by signal %d; %zu temporary file(s) removed\n", signal,
               removed);
  std::_Exit(128 + signal);
}

void take_signals_on_a_thread() {
  static sigset_t signals;  // read by the thread for the life of the process
  sigemptyset(&signals);
  for (const int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&signals, s);
  if (pthread_sigmask(SIG_BLOCK, &signals, nullptr) != 0) return;
  pthread_attr_t attributes;
  pthread_t thread;
  bool started = false;
  if (pthread_attr_init(&attributes) == 0) {
    constexpr std::size_t kStack_B = 256 * 1024;
    started = pthread_attr_setstacksize(&attributes, kStack_B) == 0 &&
              pthread_attr_setdetachstate(&attributes, PTHREAD_CREATE_DETACHED) == 0 &&
              pthread_create(&thread, &attributes, take_signals, &signals) == 0;
    pthread_attr_destroy(&attributes);
  }
  if (!started) pthread_sigmask(SIG_UNBLOCK, &signals, nullptr);
}

}  // namespace

int main(int argc, char** argv) {
  take_signals_on_a_thread();
  // A file over the size limit (ulimit -f) fails its write with EFBIG, which the writer reports
  // with the path and the reason (exit 2), instead of the signal ending the process unreported.
  std::signal(SIGXFSZ, SIG_IGN);
  using namespace dynpos::cli;
  CLI::App app{
      "dynpos " DYNPOS_VERSION
      " — dynamic positioning toolkit: identify thruster and vessel dynamics from sea-trial\n"
      "logs, calibrate GNSS/MRU lever arms, verify hybrid integral action, and run a virtual\n"
      "sea trial of R/V Gunnerus with known truth.",
      "dynpos"};
  app.set_version_flag("--version", DYNPOS_VERSION);
  app.require_subcommand(1, 1);
  app.footer(
      "Run 'dynpos SUBCOMMAND --help' for the options of each subcommand.\n"
      "Exit codes: 0 success, 1 failure, 2 bad input or options,\n"
      "128 + N stopped by signal N (130: Ctrl-C).");

  register_simulate(app);
  register_identify(app);
  register_leverarm(app);
  register_hybrid(app);
  register_compare(app);
  register_compare_trial(app);
  register_capability(app);
  register_montecarlo(app);
  register_estimate(app);
  register_consequence(app);
  register_live(app);
  register_demo(app);
  // Every output of the subcommand given is checked before any subcommand runs.
  app.parse_complete_callback([&app] { check_outputs(app); });

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitInputError;
  } catch (...) {
    const dynpos::analysis::ErrorReport error = dynpos::analysis::cli_error_report(
        std::current_exception(), std::vector<std::string>(argv + 1, argv + argc));
    fmt::print(stderr, "dynpos: error: {}\n", error.message);
    return error.input_error ? kExitInputError : kExitFailure;
  }
  return kExitOk;
}
