#include "dynpos/live/session.hpp"

#include <time.h>

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

#include "capture_file.hpp"
#include "dynpos/analysis/option_spelling.hpp"
#include "dynpos/analysis/options.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/live/http_page.hpp"
#include "dynpos/live/stream_clock.hpp"
#include "dynpos/live/stream_source.hpp"
#include "line_queue.hpp"
#include "stream_reader.hpp"

namespace dynpos::live {
namespace {

using WallClock = std::chrono::steady_clock;

/// How long a stream is quiet [s] before the data not yet analysed is.
constexpr double kQuiet_s = 1.0;
/// The longest wait of the analysis thread for lines [ms]: how often the page is served and a
/// stop request seen when nothing arrives.
constexpr std::chrono::milliseconds kWait{100};

double cpu_seconds() {
  timespec ts{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

double seconds_since(WallClock::time_point t) {
  return std::chrono::duration<double>(WallClock::now() - t).count();
}

// The CSV time column the stream clock reads: the map's, else "time".
std::string time_column(const analysis::LogSource& source) {
  const io::ColumnMap map = source.base_map();
  const io::RoleColumn* time = map.find("time");
  return time != nullptr && !time->column.empty() ? time->column : std::string("time");
}

// The session: the stream's lines into the capture, the analysis re-run on it as the schedule
// says, the lines written.
class Session {
 public:
  Session(const LiveRequest& request, std::unique_ptr<StreamSource> stream,
          const analysis::LogSource& source, const LiveAnalysis& analysis, std::FILE* out,
          std::FILE* messages)
      : request_(request),
        analysis_(analysis),
        out_(out),
        messages_(messages),
        name_(stream->name()),
        capture_(request.capture),
        clock_(time_column(source)),
        queue_(request.max_queue_bytes) {
    data_ = source;
    data_.read_from = capture_.path();
    if (!request.follow.empty()) {
      data_.log = request.follow;
    } else {
      data_.log = request.capture.empty() ? std::filesystem::path(name_) : request.capture;
    }
    fmt::print(messages_, "dynpos live: reading {}\n", name_);
    if (request.http_port) {
      page_ = std::make_unique<HttpPage>(*request.http_port, request.title + " — " + name_,
                                         "http_port");
      fmt::print(messages_, "dynpos live: page at http://127.0.0.1:{}/\n", page_->port());
    }
    std::fflush(messages_);
    // Last: the reader thread starts reading now.
    reader_ = std::make_unique<detail::StreamReader>(std::move(stream), request.strict,
                                                     request.idle_exit_s, queue_);
  }

  LiveSummary run() {
    loop();
    reader_->join();
    analyse(true);
    summary_.counts = reader_->counts();
    summary_.queue_peak_lines = queue_.peak_lines();
    summary_.queue_peak_bytes = queue_.peak_bytes();
    summary_.stream_time_s = stream_t_;
    return std::move(summary_);
  }

 private:
  void loop();
  void on_line(std::string_view line, bool whole);
  void analyse(bool final);
  double interval_s() const {
    return std::max(request_.update_s, last_cost_s_ / request_.cpu_share);
  }

  const LiveRequest& request_;
  const LiveAnalysis& analysis_;
  std::FILE* out_;
  std::FILE* messages_;
  std::string name_;  // the stream's, for messages
  detail::CaptureFile capture_;
  StreamClock clock_;
  detail::LineQueue queue_;
  std::unique_ptr<detail::StreamReader> reader_;  // after the queue it fills
  analysis::LogSource data_;
  std::unique_ptr<HttpPage> page_;
  LiveSummary summary_;
  std::optional<double> stream_t_;    // the stream time of the last timed line
  std::optional<double> next_run_t_;  // the stream time of the next run
  bool unanalysed_ = false;           // lines arrived since the last run
  double last_cost_s_ = 0.0;          // processor time of the last run
  WallClock::time_point last_run_ = WallClock::now();
  std::string last_document_;  // the last document written, compact
  std::string last_note_;
};

void Session::on_line(std::string_view line, bool whole) {
  capture_.append(line);
  unanalysed_ = true;
  if (!whole) return;
  const std::optional<double> t = clock_.read(line);
  if (!t) return;
  if (!stream_t_ || *t > *stream_t_) stream_t_ = t;
  if (!next_run_t_) next_run_t_ = *t + request_.update_s;
  if (*stream_t_ >= *next_run_t_) {
    analyse(false);
    next_run_t_ = *stream_t_ + interval_s();
  }
}

void Session::loop() {
  const auto start = WallClock::now();
  for (;;) {
    detail::LineQueue::Taken taken = queue_.take(kWait);
    if (taken.error) std::rethrow_exception(taken.error);
    for (const detail::QueuedLine& line : taken.lines) on_line(line.text, line.whole);
    if (page_) page_->serve();
    if (taken.closed) return;
    if (request_.stop && request_.stop()) reader_->request_stop();  // the rest still comes
    const double quiet_s = seconds_since(queue_.last_arrival().value_or(start));
    // Lines no run has seen: a stream gone quiet, or one whose lines carry no time.
    const bool untimed = !stream_t_ && seconds_since(last_run_) >= interval_s();
    if (unanalysed_ && (quiet_s >= kQuiet_s || untimed) &&
        seconds_since(last_run_) >= std::min(kQuiet_s, interval_s())) {
      analyse(false);
    }
  }
}

void Session::analyse(bool final) {
  capture_.flush();
  unanalysed_ = false;
  const double cpu_start = cpu_seconds();
  nlohmann::json document;
  try {
    document = analysis_(data_, final);
  } catch (const std::runtime_error& e) {
    if (final) throw;
    const auto* input = dynamic_cast<const core::InputError*>(&e);
    const std::string note = input ? analysis::cli_message(*input) : core::printable(e.what());
    if (note != last_note_) {
      fmt::print(messages_, "dynpos live: no result yet: {}\n", note);
      std::fflush(messages_);
      last_note_ = note;
    }
  }
  last_cost_s_ = cpu_seconds() - cpu_start;
  summary_.run_cpu_s += last_cost_s_;
  ++summary_.runs;
  last_run_ = WallClock::now();
  if (document.is_null()) return;
  std::string compact = document.dump();
  if (!final && compact == last_document_) return;
  const std::string line = live_line(document, stream_t_, final);
  fmt::print(out_, "{}\n", line);
  std::fflush(out_);
  ++summary_.lines_written;
  if (page_) page_->set_latest(line);
  last_document_ = std::move(compact);
  if (final) summary_.final_document = std::move(document);
}

}  // namespace

void LiveRequest::validate() const {
  const int inputs = !udp.empty() + !tcp.empty() + !follow.empty();
  if (inputs != 1) {
    throw analysis::option_error(
        "udp/tcp/follow",
        inputs == 0 ? "no stream given" : "give one stream, not " + std::to_string(inputs),
        "one of --udp HOST:PORT, --tcp HOST:PORT or --follow FILE");
  }
  if (!udp.empty()) parse_endpoint(udp, "udp");
  if (!tcp.empty()) {
    if (parse_endpoint(tcp, "tcp").port == 0) {
      throw analysis::option_error("tcp", "'" + tcp + "': a TCP server's port cannot be 0");
    }
  }
  if (idle_exit_s && !(*idle_exit_s > 0.0)) {
    throw analysis::option_error("idle_exit", "must be > 0 s");
  }
  if (!(update_s > 0.0)) throw analysis::option_error("update", "must be > 0 s");
  if (!(cpu_share > 0.0 && cpu_share <= 1.0)) {
    throw analysis::option_error("cpu_share", "must be in (0, 1]");
  }
}

std::string live_line(const nlohmann::json& document, std::optional<double> stream_time_s,
                      bool final) {
  std::string text = document.dump();
  if (!text.ends_with('}')) throw std::logic_error("a live document must be a JSON object");
  text.pop_back();
  if (text.size() > 1) text += ',';
  const nlohmann::json t = stream_time_s ? nlohmann::json(*stream_time_s) : nlohmann::json();
  return text + "\"stream_time_s\":" + t.dump() + ",\"final\":" + (final ? "true" : "false") + "}";
}

std::string summary_text(const LiveSummary& s) {
  const StreamCounts& c = s.counts;
  return fmt::format(
      "dynpos live: {} bytes, {} datagrams, {} lines ({} with a tag block, {} dropped for a bad "
      "tag block, {} other datagrams); at most {} lines ({:.1f} MB) waited for the analysis; {} "
      "runs, {:.3f} s of processor; {} JSON lines\n",
      c.bytes, c.datagrams, c.lines, c.tag_blocks, c.bad_tag_blocks, c.other_datagrams,
      s.queue_peak_lines, static_cast<double>(s.queue_peak_bytes) / 1e6, s.runs, s.run_cpu_s,
      s.lines_written);
}

std::unique_ptr<StreamSource> open_stream(const LiveRequest& r) {
  r.validate();
  if (!r.udp.empty()) return listen_udp(parse_endpoint(r.udp, "udp"), "udp");
  if (!r.tcp.empty()) return connect_tcp(parse_endpoint(r.tcp, "tcp"), "tcp");
  return follow_file(r.follow, "follow");
}

LiveSummary run_live(const LiveRequest& request, const analysis::LogSource& source,
                     const LiveAnalysis& analysis, std::FILE* out, std::FILE* messages) {
  return run_live(request, open_stream(request), source, analysis, out, messages);
}

LiveSummary run_live(const LiveRequest& request, std::unique_ptr<StreamSource> stream,
                     const analysis::LogSource& source, const LiveAnalysis& analysis,
                     std::FILE* out, std::FILE* messages) {
  request.validate();
  Session session(request, std::move(stream), source, analysis, out, messages);
  return session.run();
}

}  // namespace dynpos::live
