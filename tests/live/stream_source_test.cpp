// The stream sources: HOST:PORT, a followed file (and one cut shorter), a refused connection.

#include "dynpos/live/stream_source.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "dynpos/core/error.hpp"
#include "live_fixtures.hpp"

namespace dynpos::live {
namespace {

std::string option_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const core::InputError& e) {
    return e.option();
  }
  return "no error";
}

TEST(Endpoint, HostAndPort) {
  const Endpoint e = parse_endpoint("239.192.0.1:60001", "udp");
  EXPECT_EQ(e.host, "239.192.0.1");
  EXPECT_EQ(e.port, 60001);
  EXPECT_EQ(parse_endpoint("localhost:0", "udp").port, 0);
  for (const char* bad : {"", "10110", ":10110", "host:", "host:-1", "host:65536", "host:1x"}) {
    EXPECT_EQ(option_of([&] { parse_endpoint(bad, "tcp"); }), "tcp") << bad;
  }
}

TEST(FollowFile, ReadsWhatIsAppended) {
  test::TempDir dir;
  const auto file = dir / "grow.csv";
  test::write_lines(file, {"time,x\n", "0,1"});
  auto source = follow_file(file, "follow");
  std::vector<std::string> got;
  StreamLines lines("grow.csv", false, [&](std::string_view l, bool) { got.emplace_back(l); });
  EXPECT_TRUE(source->read(lines));
  EXPECT_EQ(got, (std::vector<std::string>{"time,x\n"}));
  std::ofstream(file, std::ios::app) << "\n1,2\n";
  EXPECT_TRUE(source->read(lines));
  EXPECT_EQ(got, (std::vector<std::string>{"time,x\n", "0,1\n", "1,2\n"}));
  test::write_lines(file, {"time,x\n"});  // cut shorter: an error naming the file
  try {
    source->read(lines);
    FAIL() << "no error";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.where().file, file.string());
  }
}

TEST(FollowFile, AMissingFileNamesTheOption) {
  EXPECT_EQ(option_of([] { follow_file("/nonexistent/dir/log.csv", "follow"); }), "follow");
}

TEST(TcpSource, ARefusedConnectionNamesTheOption) {
  // Port 1 on loopback: nothing listens there for a test user.
  EXPECT_EQ(option_of([] { connect_tcp({"127.0.0.1", 1}, "tcp"); }), "tcp");
}

}  // namespace
}  // namespace dynpos::live
