#include "dynpos/live/stream_source.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <vector>

#include "dynpos/analysis/options.hpp"
#include "dynpos/core/error.hpp"

namespace dynpos::live {
namespace {

constexpr std::size_t kReadBytes = std::size_t{1} << 16;
constexpr int kReceiveBufferBytes = 8 << 20;

// A file descriptor closed with its owner.
class Descriptor {
 public:
  explicit Descriptor(int fd) : fd_(fd) {}
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int get() const noexcept { return fd_; }

 private:
  int fd_;
};

std::string endpoint_text(const Endpoint& e) { return e.host + ":" + std::to_string(e.port); }

[[noreturn]] void fail(const std::string& key, const std::string& what, int error) {
  throw analysis::option_error(key, what + ": " + std::strerror(error));
}

// The IPv4 address of `at` (a name is resolved).
sockaddr_in resolve(const Endpoint& at, const std::string& key) {
  addrinfo hints{};
  hints.ai_family = AF_INET;
  addrinfo* found = nullptr;
  const int rc = ::getaddrinfo(at.host.c_str(), nullptr, &hints, &found);
  if (rc != 0 || found == nullptr) {
    throw analysis::option_error(key,
                                 "cannot resolve host '" + at.host + "': " + ::gai_strerror(rc));
  }
  sockaddr_in address{};
  std::memcpy(&address, found->ai_addr, sizeof address);
  ::freeaddrinfo(found);
  address.sin_port = htons(at.port);
  return address;
}

void set_non_blocking(int fd) { ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK); }

class UdpSource final : public StreamSource {
 public:
  UdpSource(const Endpoint& at, const std::string& key)
      : socket_(::socket(AF_INET, SOCK_DGRAM, 0)), buffer_(kReadBytes) {
    if (socket_.get() < 0) fail(key, "cannot open a UDP socket", errno);
    sockaddr_in address = resolve(at, key);
    const bool multicast = IN_MULTICAST(ntohl(address.sin_addr.s_addr));
    sockaddr_in bind_to = address;
    if (multicast) {  // other listeners of the group may share the port
      const int on = 1;
      ::setsockopt(socket_.get(), SOL_SOCKET, SO_REUSEADDR, &on, sizeof on);
      bind_to.sin_addr.s_addr = htonl(INADDR_ANY);
    }
    if (::bind(socket_.get(), reinterpret_cast<const sockaddr*>(&bind_to), sizeof bind_to) != 0) {
      fail(key, "cannot listen on udp " + endpoint_text(at), errno);
    }
    if (multicast) {
      ip_mreq group{};
      group.imr_multiaddr = address.sin_addr;
      group.imr_interface.s_addr = htonl(INADDR_ANY);
      if (::setsockopt(socket_.get(), IPPROTO_IP, IP_ADD_MEMBERSHIP, &group, sizeof group) != 0) {
        fail(key, "cannot join the multicast group " + at.host, errno);
      }
    }
    // Room for the datagrams that arrive while an analysis runs: as much as the system allows
    // up to kReceiveBufferBytes (net.core.rmem_max caps it), not its default of about 200 kB.
    const int receive = kReceiveBufferBytes;
    ::setsockopt(socket_.get(), SOL_SOCKET, SO_RCVBUF, &receive, sizeof receive);
    sockaddr_in bound{};
    socklen_t size = sizeof bound;
    ::getsockname(socket_.get(), reinterpret_cast<sockaddr*>(&bound), &size);
    name_ = "udp " + at.host + ":" + std::to_string(ntohs(bound.sin_port));
    set_non_blocking(socket_.get());
  }
  int fd() const override { return socket_.get(); }
  bool read(StreamLines& lines) override {
    for (;;) {
      const ssize_t n = ::recv(socket_.get(), buffer_.data(), buffer_.size(), 0);
      if (n < 0) return true;  // EAGAIN: all read; another error: the next datagram may do
      lines.add_datagram({buffer_.data(), static_cast<std::size_t>(n)});
    }
  }
  std::string name() const override { return name_; }

 private:
  Descriptor socket_;
  std::vector<char> buffer_;
  std::string name_;
};

class TcpSource final : public StreamSource {
 public:
  TcpSource(const Endpoint& to, const std::string& key)
      : socket_(::socket(AF_INET, SOCK_STREAM, 0)),
        buffer_(kReadBytes),
        name_("tcp " + endpoint_text(to)) {
    if (socket_.get() < 0) fail(key, "cannot open a TCP socket", errno);
    const sockaddr_in address = resolve(to, key);
    if (::connect(socket_.get(), reinterpret_cast<const sockaddr*>(&address), sizeof address) !=
        0) {
      fail(key, "cannot connect to " + endpoint_text(to), errno);
    }
    set_non_blocking(socket_.get());
  }
  int fd() const override { return socket_.get(); }
  bool read(StreamLines& lines) override {
    for (;;) {
      const ssize_t n = ::recv(socket_.get(), buffer_.data(), buffer_.size(), 0);
      if (n == 0) return false;
      if (n < 0) return errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR;
      lines.add_bytes({buffer_.data(), static_cast<std::size_t>(n)});
    }
  }
  std::string name() const override { return name_; }

 private:
  Descriptor socket_;
  std::vector<char> buffer_;
  std::string name_;
};

class FileSource final : public StreamSource {
 public:
  FileSource(const std::filesystem::path& file, const std::string& key)
      : file_(::open(file.c_str(), O_RDONLY | O_CLOEXEC)), buffer_(kReadBytes), name_(file) {
    if (file_.get() < 0) fail(key, "cannot open '" + file.string() + "'", errno);
  }
  int fd() const override { return -1; }
  bool read(StreamLines& lines) override {
    struct stat info {};
    if (::fstat(file_.get(), &info) == 0 && static_cast<std::uint64_t>(info.st_size) < offset_) {
      throw core::InputError({.file = name_, .line = {}, .column = {}, .column_name = {}},
                             "the file was cut shorter while it was followed (now " +
                                 std::to_string(info.st_size) + " bytes, " +
                                 std::to_string(offset_) + " read)",
                             "follow a file that is only appended to");
    }
    for (;;) {
      const ssize_t n = ::read(file_.get(), buffer_.data(), buffer_.size());
      if (n <= 0) return true;
      offset_ += static_cast<std::uint64_t>(n);
      lines.add_bytes({buffer_.data(), static_cast<std::size_t>(n)});
    }
  }
  std::string name() const override { return name_; }

 private:
  Descriptor file_;
  std::vector<char> buffer_;
  std::string name_;
  std::uint64_t offset_ = 0;
};

}  // namespace

Endpoint parse_endpoint(const std::string& text, const std::string& key) {
  const std::size_t colon = text.rfind(':');
  const auto bad = [&](const std::string& why) {
    return analysis::option_error(key, "'" + text + "' is not HOST:PORT: " + why,
                                  "for example 127.0.0.1:10110");
  };
  if (colon == std::string::npos) throw bad("no ':'");
  Endpoint out{text.substr(0, colon), 0};
  if (out.host.empty()) throw bad("no host");
  const std::string port = text.substr(colon + 1);
  unsigned value = 0;
  const auto [end, ec] = std::from_chars(port.data(), port.data() + port.size(), value);
  if (port.empty() || ec != std::errc() || end != port.data() + port.size() || value > 65535) {
    throw bad("the port must be a number from 0 to 65535");
  }
  out.port = static_cast<std::uint16_t>(value);
  return out;
}

std::unique_ptr<StreamSource> listen_udp(const Endpoint& at, const std::string& key) {
  return std::make_unique<UdpSource>(at, key);
}

std::unique_ptr<StreamSource> connect_tcp(const Endpoint& to, const std::string& key) {
  return std::make_unique<TcpSource>(to, key);
}

std::unique_ptr<StreamSource> follow_file(const std::filesystem::path& file,
                                          const std::string& key) {
  return std::make_unique<FileSource>(file, key);
}

}  // namespace dynpos::live
