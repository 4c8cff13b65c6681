// live_replay: the processor time of `dynpos live` per second of stream. Replays a log (an NMEA
// capture or a CSV log, times read as the live session reads them, live/stream_clock.hpp) over
// UDP on loopback, one datagram per line, at SPEED times real time, to a `dynpos live` it starts,
// and reports the child's processor time (user + system, wait4's rusage) per second of stream:
// at real time, that is the share of one core it takes.
//
//   live_replay DYNPOS SPEED LOG -- ANALYSIS [OPTIONS]
//   e.g. live_replay build/release/bin/dynpos 20 run/gnss1.nmea -- identify station-keeping
//
// The analysis' options follow "--"; --udp, --idle-exit and --capture are added. The live JSON
// lines go to /dev/null, the child's standard error is passed through (its summary counts the
// datagrams and lines it received, and the most that waited for its analysis thread). The
// lines received are counted in the capture and compared with the lines sent: a datagram the
// system dropped (a full receive buffer: the session's reader thread got no processor in
// time) is a line lost, which the analyses then do not see; the system-wide count of such
// drops meanwhile is printed too.

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/core.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "dynpos/live/stream_clock.hpp"

namespace {

struct Line {
  std::string text;
  std::optional<double> t_s;
};

std::vector<Line> read_lines(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + file);
  dynpos::live::StreamClock clock("time");
  std::vector<Line> lines;
  for (std::string text; std::getline(in, text);) {
    text += '\n';
    const std::optional<double> t = clock.read(text);
    lines.push_back({text, t});
  }
  return lines;
}

// The datagrams the system dropped for a full receive buffer so far (all sockets: the
// RcvbufErrors of /proc/net/snmp), or -1 where it cannot be read.
long receive_buffer_drops() {
  std::ifstream snmp("/proc/net/snmp");
  std::string names, values;
  while (std::getline(snmp, names) && std::getline(snmp, values)) {
    if (!names.starts_with("Udp:")) continue;
    std::istringstream n(names), v(values);
    for (std::string name, value; n >> name && v >> value;) {
      if (name == "RcvbufErrors") return std::stol(value);
    }
  }
  return -1;
}

// The lines of `file` (its '\n's).
std::size_t count_lines(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  std::size_t n = 0;
  for (std::string line; std::getline(in, line);) ++n;
  return n;
}

// A UDP port on loopback that nothing uses now.
int free_udp_port() {
  const int s = ::socket(AF_INET, SOCK_DGRAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ::bind(s, reinterpret_cast<sockaddr*>(&a), sizeof a);
  socklen_t size = sizeof a;
  ::getsockname(s, reinterpret_cast<sockaddr*>(&a), &size);
  ::close(s);
  return ntohs(a.sin_port);
}

// Waits until the child has bound `port` (binding it here then fails), so that no datagram is
// sent before it listens.
void wait_until_bound(int port, pid_t child) {
  for (;;) {
    const int s = ::socket(AF_INET, SOCK_DGRAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    a.sin_port = htons(static_cast<std::uint16_t>(port));
    const bool free = ::bind(s, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0;
    ::close(s);
    if (!free) return;
    int status = 0;
    if (::waitpid(child, &status, WNOHANG) == child) {
      throw std::runtime_error("dynpos live ended before it listened");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

pid_t start_live(const std::string& dynpos, const std::vector<std::string>& analysis, int port,
                 const std::string& capture) {
  std::vector<std::string> args{dynpos, "live"};
  args.insert(args.end(), analysis.begin(), analysis.end());
  for (const std::string& a :
       {std::string("--udp"), fmt::format("127.0.0.1:{}", port), std::string("--idle-exit"),
        std::string("2"), std::string("--capture"), capture}) {
    args.push_back(a);
  }
  const pid_t child = ::fork();
  if (child != 0) return child;
  const int null = ::open("/dev/null", O_WRONLY);
  ::dup2(null, STDOUT_FILENO);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  ::execv(argv[0], argv.data());
  std::_Exit(127);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 6 || std::string(argv[4]) != "--") {
    fmt::print(stderr, "usage: live_replay DYNPOS SPEED LOG -- ANALYSIS [OPTIONS]\n");
    return 2;
  }
  const std::string dynpos = argv[1];
  const double speed = std::atof(argv[2]);
  const std::vector<Line> lines = read_lines(argv[3]);
  const std::vector<std::string> analysis(argv + 5, argv + argc);
  const int port = free_udp_port();
  const std::string capture =
      (std::filesystem::temp_directory_path() / fmt::format("live_replay_{}.capture", ::getpid()))
          .string();
  const pid_t child = start_live(dynpos, analysis, port, capture);
  wait_until_bound(port, child);

  const int s = ::socket(AF_INET, SOCK_DGRAM, 0);
  sockaddr_in to{};
  to.sin_family = AF_INET;
  to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  to.sin_port = htons(static_cast<std::uint16_t>(port));
  const long drops_before = receive_buffer_drops();
  const auto start = std::chrono::steady_clock::now();
  std::optional<double> t0, t_last;
  for (const Line& line : lines) {
    if (line.t_s) {
      if (!t0) t0 = line.t_s;
      t_last = line.t_s;
      const auto due = start + std::chrono::duration<double>((*line.t_s - *t0) / speed);
      std::this_thread::sleep_until(std::chrono::time_point_cast<std::chrono::nanoseconds>(due));
    }
    ::sendto(s, line.text.data(), line.text.size(), 0, reinterpret_cast<sockaddr*>(&to), sizeof to);
  }
  ::close(s);
  int status = 0;
  rusage usage{};
  ::wait4(child, &status, 0, &usage);
  const std::size_t received = count_lines(capture);
  std::remove(capture.c_str());
  const double cpu_s = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                       static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) * 1e-6;
  const double stream_s = t0 ? *t_last - *t0 : 0.0;
  fmt::print(
      "{} lines, {:.0f} s of stream at {}x: {:.2f} s of processor, {:.4f} s per second of "
      "stream; {} lines sent, {} received, {} lost; {} datagrams dropped by full receive "
      "buffers meanwhile, system-wide (exit {})\n",
      lines.size(), stream_s, speed, cpu_s, stream_s > 0 ? cpu_s / stream_s : 0.0, lines.size(),
      received, static_cast<long>(lines.size()) - static_cast<long>(received),
      receive_buffer_drops() - drops_before, WIFEXITED(status) ? WEXITSTATUS(status) : -1);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? 0 : 1;
}
