// The local page: fixed routes, GET only, bounded requests, on 127.0.0.1.

#include "dynpos/live/http_page.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace dynpos::live {
namespace {

TEST(HttpPage, Routes) {
  const auto status = [](const std::string& head) {
    const std::string r = http_response(head, "<html>", "{\"a\":1}");
    return r.substr(0, r.find("\r\n"));
  };
  EXPECT_EQ(status("GET / HTTP/1.1\r\nHost: x\r\n\r\n"), "HTTP/1.1 200 OK");
  EXPECT_EQ(status("GET /latest.json HTTP/1.1\r\n\r\n"), "HTTP/1.1 200 OK");
  EXPECT_EQ(status("GET /../etc/passwd HTTP/1.1\r\n\r\n"), "HTTP/1.1 404 Not Found");
  EXPECT_EQ(status("POST / HTTP/1.1\r\n\r\n"), "HTTP/1.1 405 Method Not Allowed");
  EXPECT_EQ(status("GET /\r\n\r\n"), "HTTP/1.1 400 Bad Request");
  const std::string json = http_response("GET /latest.json HTTP/1.1\r\n\r\n", "", "{\"a\":1}");
  EXPECT_TRUE(json.ends_with("\r\n\r\n{\"a\":1}")) << json;
  EXPECT_NE(json.find("Content-Length: 7\r\n"), std::string::npos) << json;
}

TEST(HttpPage, ThePageEscapesItsTitle) {
  const std::string page = live_page_html("a <b> & c");
  EXPECT_NE(page.find("a &lt;b&gt; &amp; c"), std::string::npos);
  EXPECT_NE(page.find("latest.json"), std::string::npos);
}

// Sends `request` to the page on loopback and returns the answer, serving while it waits.
std::string ask(HttpPage& page, const std::string& request) {
  const int s = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in to{};
  to.sin_family = AF_INET;
  to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  to.sin_port = htons(page.port());
  EXPECT_EQ(::connect(s, reinterpret_cast<sockaddr*>(&to), sizeof to), 0);
  ::send(s, request.data(), request.size(), MSG_NOSIGNAL);
  std::string answer;
  char buffer[4096];
  for (int tries = 0; tries < 500; ++tries) {  // at most about 5 s: a failure, not a hang
    page.serve();
    pollfd p{s, POLLIN, 0};
    if (::poll(&p, 1, 10) <= 0) continue;
    const ssize_t n = ::recv(s, buffer, sizeof buffer, 0);
    if (n <= 0) break;
    answer.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(s);
  return answer;
}

TEST(HttpPage, ServesTheLatestDocumentOnLoopback) {
  HttpPage page(0, "dynpos live", "page_port");
  ASSERT_GT(page.port(), 0);
  page.set_latest("{\"final\":true}");
  const std::string answer = ask(page, "GET /latest.json HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n");
  EXPECT_TRUE(answer.starts_with("HTTP/1.1 200 OK\r\n")) << answer;
  EXPECT_TRUE(answer.ends_with("{\"final\":true}")) << answer;
  const std::string huge = "GET / HTTP/1.1\r\nX: " + std::string(HttpPage::kMaxRequestBytes, 'x');
  EXPECT_TRUE(ask(page, huge).starts_with("HTTP/1.1 431")) << "a request over the bound";
}

}  // namespace
}  // namespace dynpos::live
