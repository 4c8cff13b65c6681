#pragma once
/// \file
/// A live trial session (`dynpos live`): a stream read as it arrives into a capture file, and
/// an offline analysis re-run on the capture so far whenever new data could change its result,
/// so that the last result, at the end of the stream, is the offline analysis of the same bytes.
///
/// Two threads: a reader that waits on the stream and hands each line, as it arrives, to an
/// in-memory queue that never drops one (accounted in bytes; past LiveRequest::max_queue_bytes
/// the session ends with an error), and the caller's, which takes the lines from the queue
/// into the capture, runs the analysis and writes the results. A long run therefore never
/// leaves a UDP socket unread. The end of the stream, the idle time (by arrival) and a stop
/// request are seen by the reader; the lines already queued are analysed before the final run.
///
/// Each result is written as one JSON line: the analysis' `--json` document, compact, with
/// `"stream_time_s"` (the stream time of the last line analysed) and `"final"` (true on the
/// last line only) added at its end. A line is written when the document differs from the last
/// one written, and always at the end.
///
/// When it re-runs: by the stream's own clock (stream_clock.hpp), every `update_s` seconds of
/// stream, and not before the stream has run 1/cpu_share times as long as the last run took of
/// processor time, so that at real time the re-runs take at most that share of one core
/// however long the trial. A stream whose lines carry no time the clock can read is re-run by
/// the wall clock instead, as is the data of a stream that has gone quiet for a second.

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "dynpos/analysis/log_source.hpp"
#include "dynpos/live/stream_lines.hpp"
#include "dynpos/live/stream_source.hpp"

namespace dynpos::live {

/// What a live session reads, and how often it re-runs.
struct LiveRequest {
  std::string udp;               ///< HOST:PORT to listen on for datagrams, or ""
  std::string tcp;               ///< HOST:PORT of a TCP server to read from, or ""
  std::filesystem::path follow;  ///< a file being written, or ""
  /// End the session when nothing has arrived for this long [s] (wall clock); unset: only at
  /// the end of the stream (a TCP server closing; a UDP port or a file never ends).
  std::optional<double> idle_exit_s;
  /// The local page's port on 127.0.0.1 (0: one the system picks, printed); unset: no page.
  std::optional<std::uint16_t> http_port;
  double update_s = 1.0;    ///< stream time [s] between re-runs, at least
  double cpu_share = 0.05;  ///< the share of one core the re-runs may take at real time
  /// Keep the stream's lines (tag blocks removed) in this file; empty: a temporary file,
  /// removed at the end. With --udp or --tcp the reports name the log by it.
  std::filesystem::path capture;
  bool strict = false;                ///< a bad tag block ends the session (error naming the line)
  std::string title = "dynpos live";  ///< heads the local page
  /// The most bytes of lines that may wait for the analysis thread (text plus bookkeeping);
  /// past it the session ends with an error rather than drop lines.
  std::size_t max_queue_bytes = std::size_t{256} << 20;
  /// Asked by the analysis thread at least every 0.1 s: true ends the session as the end of the
  /// stream would (the lines received so far analysed, the final line written). E.g. a flag
  /// that a signal sets; empty: never.
  std::function<bool()> stop;

  /// Exactly one of udp, tcp and follow; update_s, cpu_share and idle_exit_s positive; the
  /// HOST:PORT texts well formed. Throws analysis::option_error naming the key.
  void validate() const;
};

/// Runs the analysis on the data so far, `data` naming the log as the offline command would
/// (the followed file, the capture, or the stream) and reading the capture. `final` is true
/// for the last run, after which the caller may write its outputs. Returns the `--json`
/// document.
using LiveAnalysis = std::function<nlohmann::json(const analysis::LogSource& data, bool final)>;

/// What a session did.
struct LiveSummary {
  StreamCounts counts;                  ///< bytes, lines, tag blocks
  std::size_t runs = 0;                 ///< analysis runs, the final one included
  std::size_t lines_written = 0;        ///< JSON lines written, the final one included
  std::optional<double> stream_time_s;  ///< the last line's stream time
  double run_cpu_s = 0.0;               ///< processor time of the runs [s]
  std::size_t queue_peak_lines = 0;     ///< the most lines that waited for the analysis thread
  std::size_t queue_peak_bytes = 0;     ///< and the most bytes (text plus bookkeeping)
  nlohmann::json final_document;        ///< the last run's document (without the added keys)
};

/// The JSON line of a document: `document` compact, with "stream_time_s" and "final" added at
/// its end (the document's own keys and bytes unchanged before them).
std::string live_line(const nlohmann::json& document, std::optional<double> stream_time_s,
                      bool final);

/// What a session did as one line (newline included), as `dynpos live` prints it at its end:
/// the bytes, datagrams and lines received, the lines that waited most, the runs and their
/// processor time, the JSON lines written.
std::string summary_text(const LiveSummary& summary);

/// Validates `request`, opens the stream and runs the session to its end: JSON lines to `out`,
/// the stream's name, the page's address and notes (a run that could not yet be made, and
/// why) to `messages`. `source` holds the log options (columns, map, formats); its log and
/// read_from are set by the session. Throws core::InputError for a bad request or stream (a
/// bad tag block with strict) and whatever the final run throws.
LiveSummary run_live(const LiveRequest& request, const analysis::LogSource& source,
                     const LiveAnalysis& analysis, std::FILE* out, std::FILE* messages);

/// The same on a stream the caller opened (e.g. a UDP port it bound first, to know the port
/// before anything is sent); the request's udp, tcp and follow only name the log.
LiveSummary run_live(const LiveRequest& request, std::unique_ptr<StreamSource> stream,
                     const analysis::LogSource& source, const LiveAnalysis& analysis,
                     std::FILE* out, std::FILE* messages);

/// Opens the stream `request` names (validated): listen_udp, connect_tcp or follow_file.
std::unique_ptr<StreamSource> open_stream(const LiveRequest& request);

}  // namespace dynpos::live
