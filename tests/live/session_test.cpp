// Live sessions end to end: a file appended in chunks (--follow), a TCP server and UDP datagrams
// on loopback (test senders on threads). The final JSON line is the offline analysis' document,
// byte for byte, plus the two keys; a step is reported before the stream ends, within 2 s of
// stream time of the moment the offline detector first finds it.

#include "dynpos/live/session.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>
#include <thread>

#include "dynpos/analysis/station_keeping.hpp"
#include "dynpos/analysis/step.hpp"
#include "live_fixtures.hpp"

namespace dynpos::live {
namespace {

using namespace std::chrono_literals;
using test::LiveLine;

analysis::StepRequest step_request(const std::filesystem::path& log) {
  analysis::StepRequest r;
  r.source.log = log;
  r.source.columns = {"input=cmd", "output=y"};
  r.source.jobs = 1;
  return r;
}

std::string offline_step(const std::filesystem::path& log) {
  return analysis::to_json(analysis::run_step(step_request(log))).dump();
}

LiveAnalysis step_analysis() {
  return [](const analysis::LogSource& data, bool) {
    analysis::StepRequest r = step_request(data.log);
    r.source = data;
    return analysis::to_json(analysis::run_step(r));
  };
}

analysis::StationKeepingRequest station_request(const std::filesystem::path& log) {
  analysis::StationKeepingRequest r;
  r.source.log = log;
  r.source.jobs = 1;
  r.duration_s = 60.0;
  return r;
}

LiveAnalysis station_analysis() {
  return [](const analysis::LogSource& data, bool) {
    analysis::StationKeepingRequest r = station_request(data.log);
    r.source = data;
    return analysis::to_json(analysis::run_station_keeping(r));
  };
}

// The session's JSON lines taken apart; every line but the last not final, the last final.
std::vector<LiveLine> lines_of(std::FILE* out) {
  std::vector<LiveLine> lines;
  for (const std::string& text : test::read_back(out)) lines.push_back(test::split_live_line(text));
  EXPECT_FALSE(lines.empty());
  for (std::size_t i = 0; i < lines.size(); ++i) {
    EXPECT_EQ(lines[i].final, i + 1 == lines.size()) << "line " << i;
  }
  return lines;
}

// The first stream time at which the offline analysis of the log cut there reports a step near
// `t_step`: the rows are cut by bisection (the step, once found, stays found).
double first_found_offline(const std::vector<std::string>& rows, double t_step,
                           const std::filesystem::path& scratch) {
  const auto found = [&](std::size_t n) {
    test::write_lines(scratch, {rows.begin(), rows.begin() + static_cast<long>(n)});
    try {
      const nlohmann::json doc = analysis::to_json(analysis::run_step(step_request(scratch)));
      for (const auto& s : doc["steps"]) {
        if (std::abs(s["t_step"].get<double>() - t_step) < 1.0) return true;
      }
    } catch (const std::exception&) {
    }
    return false;
  };
  std::size_t lo = 2, hi = rows.size();  // found(hi), not found(lo)
  EXPECT_TRUE(found(hi));
  while (hi - lo > 1) {
    const std::size_t mid = (lo + hi) / 2;
    (found(mid) ? hi : lo) = mid;
  }
  return std::stod(rows[hi - 1]);  // the time of the last row of the shortest log
}

TEST(LiveSession, FollowAFileAppendedInChunksEndsInTheOfflineDocument) {
  test::TempDir dir;
  const std::vector<std::string> rows = test::step_csv();
  const std::filesystem::path log = dir / "trial.csv";
  test::write_lines(log, {rows.begin(), rows.begin() + 50});
  std::thread writer([&] {  // the logger: 2 s of stream per chunk
    for (std::size_t at = 50; at < rows.size(); at += 20) {
      std::this_thread::sleep_for(5ms);
      std::ofstream out(log, std::ios::app | std::ios::binary);
      for (std::size_t i = at; i < std::min(rows.size(), at + 20); ++i) out << rows[i];
    }
  });
  LiveRequest request;
  request.follow = log;
  request.idle_exit_s = 3.0;
  std::FILE* out = std::tmpfile();
  std::FILE* messages = std::tmpfile();
  const LiveSummary summary =
      run_live(request, step_request(log).source, step_analysis(), out, messages);
  writer.join();
  const std::vector<LiveLine> lines = lines_of(out);
  ASSERT_GE(lines.size(), 2u);
  // The final document, byte for byte, is the offline one of the whole file.
  EXPECT_EQ(lines.back().document, offline_step(log));
  EXPECT_EQ(lines.back().stream_time_s, 100.0);
  EXPECT_EQ(summary.final_document.dump(), lines.back().document);
  EXPECT_EQ(summary.counts.lines, rows.size());
  // Each step is reported before the end, within 2 s of stream time of the offline detector's
  // first finding it (by the default update of 1 s: at most 1 s plus a row).
  for (const double t_step : test::kStepTimes) {
    const double found_s = first_found_offline(rows, t_step, dir / "prefix.csv");
    std::optional<double> reported_s;
    for (const LiveLine& line : lines) {
      const nlohmann::json doc = nlohmann::json::parse(line.document);
      for (const auto& s : doc["steps"]) {
        if (!reported_s && std::abs(s["t_step"].get<double>() - t_step) < 1.0) {
          reported_s = line.stream_time_s;
        }
      }
    }
    ASSERT_TRUE(reported_s) << "step at " << t_step << " s never reported";
    EXPECT_LT(*reported_s, 100.0) << "step at " << t_step << " s reported only at the end";
    EXPECT_GE(*reported_s, found_s) << "step at " << t_step;
    EXPECT_LE(*reported_s, found_s + 2.0) << "step at " << t_step;
  }
  std::fclose(out);
  std::fclose(messages);
}

// A TCP server on loopback that sends `text` to its one client and closes.
class TcpSender {
 public:
  explicit TcpSender(std::string text) : text_(std::move(text)) {
    listener_ = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    EXPECT_EQ(::bind(listener_, reinterpret_cast<sockaddr*>(&a), sizeof a), 0);
    EXPECT_EQ(::listen(listener_, 1), 0);
    socklen_t size = sizeof a;
    ::getsockname(listener_, reinterpret_cast<sockaddr*>(&a), &size);
    port_ = ntohs(a.sin_port);
    thread_ = std::thread([this] {
      const int client = ::accept(listener_, nullptr, nullptr);
      for (std::size_t at = 0; at < text_.size(); at += 1000) {  // in pieces, cut anywhere
        ::send(client, text_.data() + at, std::min<std::size_t>(1000, text_.size() - at), 0);
        std::this_thread::sleep_for(1ms);
      }
      ::close(client);
    });
  }
  ~TcpSender() {
    thread_.join();
    ::close(listener_);
  }
  int port() const { return port_; }

 private:
  std::string text_;
  int listener_ = -1;
  int port_ = 0;
  std::thread thread_;
};

// The capture with tag blocks before each sentence and one line whose tag block is spoilt; and
// what the session should keep of it.
struct Tagged {
  std::vector<std::string> sent;
  std::string kept;
};

Tagged tagged_capture(int seconds) {
  Tagged out;
  const std::vector<std::string> capture = test::station_capture(seconds);
  for (std::size_t i = 0; i < capture.size(); ++i) {
    const bool spoilt = i == 7;
    out.sent.push_back(test::tag_block(1714557600 + static_cast<long>(i / 2), spoilt) + capture[i]);
    if (!spoilt) out.kept += capture[i];
  }
  return out;
}

std::string file_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(LiveSession, TcpWithTagBlocksEndsInTheOfflineDocumentOfTheCapture) {
  test::TempDir dir;
  const Tagged capture = tagged_capture(150);
  std::string text;
  for (const std::string& line : capture.sent) text += line;
  TcpSender sender(text);
  LiveRequest request;
  request.tcp = "127.0.0.1:" + std::to_string(sender.port());
  request.capture = dir / "tcp.nmea";
  std::FILE* out = std::tmpfile();
  std::FILE* messages = std::tmpfile();
  const LiveSummary summary =
      run_live(request, station_request("").source, station_analysis(), out, messages);
  const std::vector<LiveLine> lines = lines_of(out);
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(file_text(request.capture), capture.kept);
  EXPECT_EQ(summary.counts.bad_tag_blocks, 1u);
  EXPECT_EQ(summary.counts.tag_blocks, capture.sent.size() - 1);
  const std::string offline =
      analysis::to_json(analysis::run_station_keeping(station_request(request.capture))).dump();
  EXPECT_EQ(lines.back().document, offline);
  // The moving window: the results before the end are of other windows.
  EXPECT_GT(lines.size(), 2u);
  std::fclose(out);
  std::fclose(messages);
}

TEST(LiveSession, UdpDatagramsWithTheUdPbCHeader) {
  test::TempDir dir;
  const Tagged capture = tagged_capture(100);
  auto stream = listen_udp({"127.0.0.1", 0}, "udp");
  const std::string name = stream->name();
  const int port = std::stoi(name.substr(name.rfind(':') + 1));
  ASSERT_GT(port, 0);
  // Sent while the session runs; datagrams sent before it polls wait in the bound socket.
  std::thread sender([&] {
    const int s = ::socket(AF_INET, SOCK_DGRAM, 0);
    sockaddr_in to{};
    to.sin_family = AF_INET;
    to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    to.sin_port = htons(static_cast<std::uint16_t>(port));
    for (const std::string& line : capture.sent) {
      const std::string datagram = std::string("UdPbC\0", 6) + line;
      ::sendto(s, datagram.data(), datagram.size(), 0, reinterpret_cast<sockaddr*>(&to), sizeof to);
      std::this_thread::sleep_for(200us);
    }
    ::close(s);
  });
  LiveRequest request;
  request.udp = "127.0.0.1:0";
  request.idle_exit_s = 1.0;
  request.capture = dir / "udp.nmea";
  std::FILE* out = std::tmpfile();
  std::FILE* messages = std::tmpfile();
  const LiveSummary summary = run_live(request, std::move(stream), station_request("").source,
                                       station_analysis(), out, messages);
  sender.join();
  const std::vector<LiveLine> lines = lines_of(out);
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(summary.counts.bad_tag_blocks, 1u);
  EXPECT_EQ(file_text(request.capture), capture.kept);
  const std::string offline =
      analysis::to_json(analysis::run_station_keeping(station_request(request.capture))).dump();
  EXPECT_EQ(lines.back().document, offline);
  std::fclose(out);
  std::fclose(messages);
}

// A UDP socket of `stream` (listen_udp) and its port; its receive buffer set to `bytes` (the
// system doubles it for its bookkeeping).
int udp_port(const StreamSource& stream, int receive_bytes) {
  ::setsockopt(stream.fd(), SOL_SOCKET, SO_RCVBUF, &receive_bytes, sizeof receive_bytes);
  const std::string name = stream.name();
  return std::stoi(name.substr(name.rfind(':') + 1));
}

// Sends each of `lines` as a datagram to 127.0.0.1:`port`, 0.2 ms apart.
void send_datagrams(int port, const std::vector<std::string>& lines) {
  const int s = ::socket(AF_INET, SOCK_DGRAM, 0);
  sockaddr_in to{};
  to.sin_family = AF_INET;
  to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  to.sin_port = htons(static_cast<std::uint16_t>(port));
  for (const std::string& line : lines) {
    ::sendto(s, line.data(), line.size(), 0, reinterpret_cast<sockaddr*>(&to), sizeof to);
    std::this_thread::sleep_for(200us);
  }
  ::close(s);
}

// An analysis far slower than the stream: each run waits 0.3 s, then counts the capture's lines.
LiveAnalysis slow_line_count() {
  return [](const analysis::LogSource& data, bool) {
    std::this_thread::sleep_for(300ms);
    std::ifstream in(data.read_from, std::ios::binary);
    std::size_t n = 0;
    for (std::string line; std::getline(in, line);) ++n;
    return nlohmann::json{{"lines", n}};
  };
}

// The analysis runs back to back (every 20 s of a 10 Hz stream, each 0.3 s of wall clock)
// while 1501 datagrams come 0.2 ms apart, the first run starting at the 200th, into a receive
// buffer that holds a few hundred: a session that read the socket only between runs would lose
// many of them. The reader thread takes each as it comes; the capture is what was sent.
TEST(LiveSession, ASlowAnalysisLosesNoDatagram) {
  test::TempDir dir;
  const std::vector<std::string> rows = test::step_csv(150.0);
  auto stream = listen_udp({"127.0.0.1", 0}, "udp");
  const int port = udp_port(*stream, 256 * 1024);
  std::thread sender([&] { send_datagrams(port, rows); });
  LiveRequest request;
  request.udp = "127.0.0.1:0";
  request.idle_exit_s = 1.0;
  request.update_s = 20.0;
  request.capture = dir / "slow.csv";
  std::FILE* out = std::tmpfile();
  std::FILE* messages = std::tmpfile();
  const LiveSummary summary = run_live(request, std::move(stream), step_request("").source,
                                       slow_line_count(), out, messages);
  sender.join();
  std::string sent;
  for (const std::string& row : rows) sent += row;
  EXPECT_EQ(summary.counts.datagrams, rows.size());
  EXPECT_EQ(file_text(request.capture), sent);
  const std::vector<LiveLine> lines = lines_of(out);
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(lines.back().document, nlohmann::json({{"lines", rows.size()}}).dump());
  EXPECT_GT(summary.queue_peak_lines, 1u);  // lines waited while a run went on
  std::fclose(out);
  std::fclose(messages);
}

// Lines that would wait beyond the queue's bound end the session with an error naming it,
// never a line silently dropped.
TEST(LiveSession, AQueueOverItsBoundIsAnError) {
  const std::vector<std::string> rows = test::step_csv(60.0);
  auto stream = listen_udp({"127.0.0.1", 0}, "udp");
  const int port = udp_port(*stream, 1 << 20);
  std::thread sender([&] { send_datagrams(port, rows); });
  LiveRequest request;
  request.udp = "127.0.0.1:0";
  request.idle_exit_s = 1.0;
  request.update_s = 0.1;
  request.max_queue_bytes = 2000;
  std::FILE* out = std::tmpfile();
  std::FILE* messages = std::tmpfile();
  try {
    run_live(request, std::move(stream), step_request("").source, slow_line_count(), out, messages);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("reached the bound of"), std::string::npos) << e.what();
  }
  sender.join();
  std::fclose(out);
  std::fclose(messages);
}

// A stop request (Ctrl-C in the command) ends a UDP session, which has no end of its own, with
// its final line: every datagram sent before the request is in it.
TEST(LiveSession, AStopRequestEndsWithTheFinalLine) {
  test::TempDir dir;
  const std::vector<std::string> rows = test::step_csv(30.0);
  auto stream = listen_udp({"127.0.0.1", 0}, "udp");
  const int port = udp_port(*stream, 1 << 20);
  std::atomic<bool> stop{false};
  std::thread sender([&] {
    send_datagrams(port, rows);
    stop.store(true);
  });
  LiveRequest request;
  request.udp = "127.0.0.1:0";
  request.capture = dir / "stopped.csv";
  request.stop = [&stop] { return stop.load(); };
  std::FILE* out = std::tmpfile();
  std::FILE* messages = std::tmpfile();
  const LiveSummary summary =
      run_live(request, std::move(stream), step_request("").source, step_analysis(), out, messages);
  sender.join();
  const std::vector<LiveLine> lines = lines_of(out);
  ASSERT_FALSE(lines.empty());
  EXPECT_TRUE(lines.back().final);
  EXPECT_EQ(summary.counts.lines, rows.size());
  EXPECT_EQ(lines.back().document, offline_step(request.capture));
  std::fclose(out);
  std::fclose(messages);
}

TEST(LiveSession, StrictEndsAtABadTagBlockNamingItsLine) {
  const Tagged capture = tagged_capture(10);
  std::string text;
  for (const std::string& line : capture.sent) text += line;
  TcpSender sender(text);
  LiveRequest request;
  request.tcp = "127.0.0.1:" + std::to_string(sender.port());
  request.strict = true;
  std::FILE* out = std::tmpfile();
  std::FILE* messages = std::tmpfile();
  try {
    run_live(request, station_request("").source, station_analysis(), out, messages);
    FAIL() << "no error";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.where().line, 8u) << e.what();
    EXPECT_NE(std::string(e.what()).find("tcp 127.0.0.1:"), std::string::npos) << e.what();
  }
  std::fclose(out);
  std::fclose(messages);
}

TEST(LiveSession, TheAddedKeysAreAtTheEnd) {
  const nlohmann::json doc = {{"b", 1}, {"a", nullptr}};
  EXPECT_EQ(live_line(doc, 12.5, false), R"({"a":null,"b":1,"stream_time_s":12.5,"final":false})");
  EXPECT_EQ(live_line(nlohmann::json::object(), std::nullopt, true),
            R"({"stream_time_s":null,"final":true})");
}

TEST(LiveSession, TheRequestNamesItsBadOption) {
  const auto message = [](const LiveRequest& r) {
    try {
      r.validate();
    } catch (const core::InputError& e) {
      return e.option() + ": " + e.what();
    }
    return std::string("no error");
  };
  LiveRequest none;
  EXPECT_NE(message(none).find("udp/tcp/follow"), std::string::npos);
  LiveRequest two;
  two.udp = "127.0.0.1:1";
  two.follow = "x.csv";
  EXPECT_NE(message(two).find("udp/tcp/follow"), std::string::npos);
  LiveRequest bad;
  bad.udp = "127.0.0.1:70000";
  EXPECT_EQ(message(bad).substr(0, 4), "udp:");
  bad.udp = "localhost";
  EXPECT_EQ(message(bad).substr(0, 4), "udp:");
  LiveRequest tcp0;
  tcp0.tcp = "127.0.0.1:0";
  EXPECT_EQ(message(tcp0).substr(0, 4), "tcp:");
  LiveRequest idle;
  idle.follow = "x.csv";
  idle.idle_exit_s = 0.0;
  EXPECT_EQ(message(idle).substr(0, 10), "idle_exit:");
}

}  // namespace
}  // namespace dynpos::live
