#include "dynpos/live/http_page.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>

#include "dynpos/analysis/options.hpp"
#include "dynpos/io/markup.hpp"

namespace dynpos::live {
namespace {

std::string response(const char* status, const char* type, const std::string& body) {
  return fmt::format(
      "HTTP/1.1 {}\r\nContent-Type: {}\r\nContent-Length: {}\r\nCache-Control: no-store\r\n"
      "Connection: close\r\n\r\n{}",
      status, type, body.size(), body);
}

// Writes all of `text`, waiting at most about a second for a slow reader.
void send_all(int fd, const std::string& text) {
  std::size_t sent = 0;
  for (int tries = 0; sent < text.size() && tries < 100;) {
    const ssize_t n = ::send(fd, text.data() + sent, text.size() - sent, MSG_NOSIGNAL);
    if (n > 0) {
      sent += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) return;
    pollfd p{fd, POLLOUT, 0};
    ::poll(&p, 1, 10);
    ++tries;
  }
}

}  // namespace

std::string http_response(const std::string& request_head, const std::string& page,
                          const std::string& latest) {
  const std::size_t line_end = request_head.find("\r\n");
  if (line_end == std::string::npos || request_head.find("\r\n\r\n") == std::string::npos) {
    return response("400 Bad Request", "text/plain", "bad request\n");
  }
  const std::string line = request_head.substr(0, line_end);
  const std::size_t space = line.find(' ');
  const std::size_t space2 = line.find(' ', space + 1);
  if (space == std::string::npos || space2 == std::string::npos) {
    return response("400 Bad Request", "text/plain", "bad request\n");
  }
  const std::string method = line.substr(0, space);
  const std::string path = line.substr(space + 1, space2 - space - 1);
  if (method != "GET") return response("405 Method Not Allowed", "text/plain", "GET only\n");
  if (path == "/" || path == "/index.html") {
    return response("200 OK", "text/html; charset=utf-8", page);
  }
  if (path == "/latest.json") return response("200 OK", "application/json", latest);
  return response("404 Not Found", "text/plain", "not found\n");
}

HttpPage::HttpPage(std::uint16_t port, const std::string& title, const std::string& key)
    : page_(live_page_html(title)) {
  listener_ = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (listener_ < 0) {
    throw analysis::option_error(key, std::string("cannot open a socket: ") + std::strerror(errno));
  }
  const int on = 1;
  ::setsockopt(listener_, SOL_SOCKET, SO_REUSEADDR, &on, sizeof on);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = htons(port);
  if (::bind(listener_, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0 ||
      ::listen(listener_, 16) != 0) {
    const int error = errno;
    ::close(listener_);
    throw analysis::option_error(
        key, fmt::format("cannot listen on 127.0.0.1:{}: {}", port, std::strerror(error)),
        "give another port, or 0 for one the system picks");
  }
  socklen_t size = sizeof address;
  ::getsockname(listener_, reinterpret_cast<sockaddr*>(&address), &size);
  port_ = ntohs(address.sin_port);
}

HttpPage::~HttpPage() {
  for (const Connection& c : connections_) ::close(c.fd);
  ::close(listener_);
}

void HttpPage::add_fds(std::vector<pollfd>& fds) const {
  if (connections_.size() < kMaxConnections) fds.push_back({listener_, POLLIN, 0});
  for (const Connection& c : connections_) fds.push_back({c.fd, POLLIN, 0});
}

void HttpPage::answer(Connection& c) {
  send_all(c.fd, http_response(c.request, page_, latest_));
  ::close(c.fd);
  c.fd = -1;
}

void HttpPage::serve() {
  while (connections_.size() < kMaxConnections) {
    const int fd = ::accept4(listener_, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
    if (fd < 0) break;
    connections_.push_back({fd, {}});
  }
  std::array<char, 4096> buffer{};
  for (Connection& c : connections_) {
    for (;;) {
      const ssize_t n = ::recv(c.fd, buffer.data(), buffer.size(), 0);
      if (n == 0 || (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)) {
        ::close(c.fd);
        c.fd = -1;
        break;
      }
      if (n < 0) break;
      c.request.append(buffer.data(), static_cast<std::size_t>(n));
      if (c.request.find("\r\n\r\n") != std::string::npos) {
        answer(c);
        break;
      }
      if (c.request.size() > kMaxRequestBytes) {
        send_all(c.fd, response("431 Request Header Fields Too Large", "text/plain",
                                "request too large\n"));
        ::close(c.fd);
        c.fd = -1;
        break;
      }
    }
  }
  std::erase_if(connections_, [](const Connection& c) { return c.fd < 0; });
}

}  // namespace dynpos::live
