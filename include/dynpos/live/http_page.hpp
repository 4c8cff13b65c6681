#pragma once
/// \file
/// The local page of a live session: a small HTTP/1.1 server bound to 127.0.0.1 only, with two
/// fixed routes, GET / (one HTML page that fetches the latest document every second and shows
/// its numbers as tables and the series as plots) and GET /latest.json (the latest JSON line).
/// Anything else is 404 (405 for another method); a request head over 8 KiB is refused; each
/// connection answers one request and is closed. It runs on the session's analysis thread, which
/// calls serve() whenever it wakes (lines arrived, or 0.1 s passed), between runs.

#include <poll.h>

#include <cstdint>
#include <string>
#include <vector>

namespace dynpos::live {

class HttpPage {
 public:
  /// The largest request head read [bytes].
  static constexpr std::size_t kMaxRequestBytes = 8 * 1024;
  /// The most connections open at once; more wait in the listen queue.
  static constexpr std::size_t kMaxConnections = 8;

  /// Listens on 127.0.0.1:`port` (0: a port the system picks). `title` heads the page.
  /// Throws analysis::option_error(key) when the port cannot be bound.
  HttpPage(std::uint16_t port, const std::string& title, const std::string& key);
  ~HttpPage();
  HttpPage(const HttpPage&) = delete;
  HttpPage& operator=(const HttpPage&) = delete;

  /// The port it listens on.
  std::uint16_t port() const noexcept { return port_; }
  /// Appends the descriptors to poll for reading: the listener and the open connections.
  void add_fds(std::vector<pollfd>& fds) const;
  /// Accepts and answers what is ready, without blocking on a slow client.
  void serve();
  /// The document GET /latest.json returns from now on.
  void set_latest(std::string json) { latest_ = std::move(json); }

 private:
  struct Connection {
    int fd;
    std::string request;
  };
  void answer(Connection& c);

  int listener_ = -1;
  std::uint16_t port_ = 0;
  std::string page_;
  std::string latest_ = "{}";
  std::vector<Connection> connections_;
};

/// The HTML page (self-contained: style and script inline).
std::string live_page_html(const std::string& title);

/// The HTTP response to a request head: "GET / …" → the page, "GET /latest.json …" → `latest`,
/// other paths 404, other methods 405, a head without its end 400.
std::string http_response(const std::string& request_head, const std::string& page,
                          const std::string& latest);

}  // namespace dynpos::live
