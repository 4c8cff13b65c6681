#pragma once
/// \file
/// Where a live stream comes from: NMEA datagrams on a UDP port (unicast, or an IEC 61162-450
/// multicast group), a TCP server that sends lines (a gateway's NMEA port), or a file that a
/// logger is still writing. POSIX sockets, read without blocking; the caller polls fd().

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "dynpos/live/stream_lines.hpp"

namespace dynpos::live {

/// A host (name or IPv4 address) and a port.
struct Endpoint {
  std::string host;
  std::uint16_t port = 0;
};

/// "HOST:PORT" (PORT 0–65535) → Endpoint; throws analysis::option_error(key) for another text.
Endpoint parse_endpoint(const std::string& text, const std::string& key);

class StreamSource {
 public:
  virtual ~StreamSource() = default;
  /// The descriptor to poll for input; -1 for a file, read at every wake.
  virtual int fd() const = 0;
  /// Passes what has arrived to `lines`, without blocking; false once the stream has ended
  /// (the TCP peer closed; never for UDP or a file).
  virtual bool read(StreamLines& lines) = 0;
  /// "udp 127.0.0.1:10110", "tcp HOST:PORT" or the file, for messages.
  virtual std::string name() const = 0;
};

/// Listens for datagrams on `at` (port 0: one the system picks, shown by name()); a multicast
/// group address is joined on every interface. Throws core::InputError naming `key` when the
/// address cannot be resolved or bound.
std::unique_ptr<StreamSource> listen_udp(const Endpoint& at, const std::string& key);
/// Connects to a TCP server. Throws core::InputError naming `key` when it cannot.
std::unique_ptr<StreamSource> connect_tcp(const Endpoint& to, const std::string& key);
/// Reads `file` from its start and then what is appended to it. Throws core::InputError naming
/// `key` when it cannot be opened, and naming the file when it is cut shorter than read.
std::unique_ptr<StreamSource> follow_file(const std::filesystem::path& file,
                                          const std::string& key);

}  // namespace dynpos::live
