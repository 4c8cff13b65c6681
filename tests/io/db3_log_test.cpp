#include "dynpos/io/db3_log.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <fmt/format.h>

#include "db3_test_writer.hpp"
#include "dynpos/io/bag_log.hpp"
#include "dynpos/io/cdr_decoder.hpp"
#include "dynpos/io/csv_reader.hpp"
#include "dynpos/io/db3_reader.hpp"
#include "io_test_util.hpp"
#include "mcap_test_writer.hpp"

namespace dynpos::io {
namespace {

using testing::Bytes;
using testing::CdrWriter;
using testing::Db3Writer;
using ::testing::HasSubstr;
using testing::input_error_message;
using testing::McapLayout;
using testing::McapWriter;
using testing::TempDir;

constexpr std::int64_t kStart = 1'714'557'600'000'000'000;  // 2024-05-01T10:00:00Z [ns]

// The test's own field lists of the types it writes (the MCAP carries them; the .db3 files
// rely on the built-in set or their message_definitions table).
const std::map<std::string, std::string>& definitions() {
  static const std::map<std::string, std::string> d = {
      {"std_msgs/Float64", "float64 data\n"},
      {"builtin_interfaces/Time", "int32 sec\nuint32 nanosec\n"},
      {"std_msgs/Header", "builtin_interfaces/Time stamp\nstring frame_id\n"},
      {"geometry_msgs/Vector3", "float64 x\nfloat64 y\nfloat64 z\n"},
      {"geometry_msgs/Point", "float64 x\nfloat64 y\nfloat64 z\n"},
      {"geometry_msgs/Quaternion", "float64 x\nfloat64 y\nfloat64 z\nfloat64 w\n"},
      {"geometry_msgs/Pose",
       "geometry_msgs/Point position\ngeometry_msgs/Quaternion orientation\n"},
      {"geometry_msgs/PoseWithCovariance", "geometry_msgs/Pose pose\nfloat64[36] covariance\n"},
      {"geometry_msgs/Twist", "geometry_msgs/Vector3 linear\ngeometry_msgs/Vector3 angular\n"},
      {"geometry_msgs/TwistWithCovariance", "geometry_msgs/Twist twist\nfloat64[36] covariance\n"},
      {"sensor_msgs/Imu",
       "std_msgs/Header header\ngeometry_msgs/Quaternion orientation\nfloat64[9] oc\n"
       "geometry_msgs/Vector3 angular_velocity\nfloat64[9] ac\n"
       "geometry_msgs/Vector3 linear_acceleration\nfloat64[9] lc\n"},
      {"sensor_msgs/JointState",
       "std_msgs/Header header\nstring[] name\nfloat64[] position\nfloat64[] velocity\n"
       "float64[] effort\n"},
      {"nav_msgs/Odometry",
       "std_msgs/Header header\nstring child_frame_id\ngeometry_msgs/PoseWithCovariance pose\n"
       "geometry_msgs/TwistWithCovariance twist\n"},
      {"sensor_msgs/NavSatStatus", "int8 status\nuint16 service\n"},
      {"sensor_msgs/NavSatFix",
       "std_msgs/Header header\nsensor_msgs/NavSatStatus status\nfloat64 latitude\n"
       "float64 longitude\nfloat64 altitude\nfloat64[9] position_covariance\n"
       "uint8 position_covariance_type\n"},
  };
  return d;
}

// The MCAP schema of `root` ("pkg/msg/Type"): its definition, then each of `nested`'s.
std::string schema_text(const std::string& root, const std::vector<std::string>& nested) {
  std::string text = definitions().at(ros2_type_name(root));
  for (const std::string& n : nested) {
    text += std::string(80, '=') + "\nMSG: " + n + "\n" + definitions().at(n);
  }
  return text;
}

struct Topic {
  std::string name;
  std::string type;
  std::vector<std::string> nested;
};
struct Message {
  std::size_t topic;
  std::int64_t receive_ns;
  Bytes data;
};
struct Bag {
  std::vector<Topic> topics;
  std::vector<Message> messages;
};

const std::vector<std::string> kHeader = {"std_msgs/Header", "builtin_interfaces/Time"};

std::vector<std::string> with_header(std::vector<std::string> more) {
  more.insert(more.end(), kHeader.begin(), kHeader.end());
  return more;
}

CdrWriter& vector3(CdrWriter& w, double x, double y, double z) { return w.put(x).put(y).put(z); }
CdrWriter& covariance(CdrWriter& w, std::size_t n, double scale) {
  for (std::size_t i = 0; i < n; ++i) w.put(scale * static_cast<double>(i + 1));
  return w;
}

// 50 samples of each topic at 10 Hz (the commands at receive time only), out of order at the
// end, with one repeated time.
Bag vessel_bag() {
  Bag bag;
  bag.topics = {
      {"/cmd", "std_msgs/msg/Float64", {}},
      {"/imu", "sensor_msgs/msg/Imu",
       with_header({"geometry_msgs/Quaternion", "geometry_msgs/Vector3"})},
      {"/joints", "sensor_msgs/msg/JointState", kHeader},
      {"/odom", "nav_msgs/msg/Odometry",
       with_header({"geometry_msgs/PoseWithCovariance", "geometry_msgs/Pose", "geometry_msgs/Point",
                    "geometry_msgs/Quaternion", "geometry_msgs/TwistWithCovariance",
                    "geometry_msgs/Twist", "geometry_msgs/Vector3"})},
      {"/fix", "sensor_msgs/msg/NavSatFix", with_header({"sensor_msgs/NavSatStatus"})},
  };
  for (int k = 0; k < 50; ++k) {
    const std::int64_t t = kStart + 100'000'000LL * k;
    const double x = 0.1 * k;
    bag.messages.push_back({0, t + 1'000'000, CdrWriter().put(x < 2.0 ? 0.0 : 1.5).bytes()});
    CdrWriter imu;
    imu.header(t - 3'000'000, "imu_link").put(0.0).put(0.0).put(std::sin(x)).put(std::cos(x));
    covariance(imu, 9, 0.01);
    vector3(imu, 0.01 * x, -0.02 * x, 1.0 / (1.0 + x));
    covariance(imu, 9, 0.02);
    vector3(imu, 0.3, -0.1, 9.81);
    covariance(imu, 9, 0.03);
    bag.messages.push_back({1, t + 2'000'000, imu.bytes()});
    CdrWriter joints;
    joints.header(t, "").put(std::uint32_t{2}).string("port").string("stbd");
    joints.put(std::uint32_t{2}).put(x).put(-x).put(std::uint32_t{0}).put(std::uint32_t{1});
    joints.put(0.5 * x);
    bag.messages.push_back({2, t + 3'000'000, joints.bytes()});
    CdrWriter odom;
    odom.header(t + 5'000'000, "odom").string("base_link");
    vector3(odom, 100.0 + x, -20.0 * x, 0.0).put(0.0).put(0.0).put(std::sin(x / 2)).put(1.0);
    covariance(odom, 36, 1e-3 * (1 + k));
    vector3(odom, 2.5 + x * x, 0.1, 0.0);
    vector3(odom, 0.0, 0.0, 0.01 * k);
    covariance(odom, 36, 1e-4);
    bag.messages.push_back({3, t + 6'000'000, odom.bytes()});
    if (k % 5 == 0) {  // a slower receiver, at 2 Hz
      CdrWriter fix;
      fix.header(t, "gps").put(std::int8_t{1}).put(std::uint16_t{1});
      fix.put(63.4 + 1e-6 * k).put(10.4 - 2e-6 * k).put(45.0 + x);
      covariance(fix, 9, 0.5).put(std::uint8_t{2});
      bag.messages.push_back({4, t + 9'000'000, fix.bytes()});
    }
  }
  std::swap(bag.messages[bag.messages.size() - 2], bag.messages[bag.messages.size() - 7]);
  bag.messages.push_back(bag.messages[1]);  // a repeated /imu message (same stamp)
  bag.messages.back().receive_ns += 50;
  return bag;
}

void write_mcap(const Bag& bag, const std::filesystem::path& path) {
  McapWriter w(McapLayout{true, "zstd", 40, true, true});
  std::vector<std::uint16_t> channels;
  for (const Topic& t : bag.topics) {
    channels.push_back(w.channel(w.schema(t.type, schema_text(t.type, t.nested)), t.name));
  }
  for (const Message& m : bag.messages) {
    w.message(channels[m.topic], static_cast<std::uint64_t>(m.receive_ns), m.data);
  }
  w.write(path);
}

// The bag as .db3: topic ids from 7 on in reverse order; with `stored`, the definitions in the
// message_definitions table (rosbag2 since Iron), else none (the built-in set is used).
void write_db3(const Bag& bag, const std::filesystem::path& path, bool stored) {
  Db3Writer w(path, stored);
  const auto id = [&](std::size_t topic) {
    return static_cast<std::int64_t>(7 + bag.topics.size() - topic);
  };
  for (std::size_t i = 0; i < bag.topics.size(); ++i) {
    const Topic& t = bag.topics[i];
    w.topic(id(i), t.name, t.type);
    if (stored) w.definition(t.type, "ros2msg", schema_text(t.type, t.nested));
  }
  for (const Message& m : bag.messages) w.message(id(m.topic), m.receive_ns, m.data);
}

ColumnMap vessel_map() {
  ColumnMap map;
  map.set_column("time", "/imu");
  map.set_column("input", "/cmd.data");
  map.set_column("output", "/imu.angular_velocity.z");
  map.set_column("heading", "/imu.orientation.z");
  map.set_column("r", "/joints.position[1]");
  map.set_column("p", "/joints.effort[0]");
  map.set_column("q", "/joints.velocity[0]");  // an empty sequence: missing
  map.set_column("north", "/odom.pose.pose.position.x");
  map.set_column("east", "/odom.pose.covariance[35]");
  map.set_column("u", "/odom.twist.twist.linear.x");
  map.set_column("lat", "/fix.latitude");
  map.set_column("lon", "/fix.longitude");
  map.set_column("height", "/fix.altitude");
  return map;
}

// |a - b| <= 1e-12 |b|, or both NaN: the tolerance the bag formats are held to (the same bytes
// are decoded; a reader that differs by a rounding step fails it).
void expect_close(const std::vector<double>& a, const std::vector<double>& b,
                  const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::isnan(b[i])) {
      EXPECT_TRUE(std::isnan(a[i])) << what << "[" << i << "]";
      continue;
    }
    EXPECT_LE(std::abs(a[i] - b[i]), 1e-12 * std::abs(b[i])) << what << "[" << i << "]";
  }
}

void expect_same_topic(const FileLog& a, const FileLog& b) {
  EXPECT_EQ(a.report.topic, b.report.topic);
  EXPECT_EQ(a.report.time_format, b.report.time_format);
  EXPECT_EQ(a.report.records, b.report.records);
  EXPECT_EQ(a.report.skipped.count("repeated time"), b.report.skipped.count("repeated time"));
  EXPECT_EQ(a.origin_ns, b.origin_ns) << a.report.topic;
  expect_close(a.log.time(), b.log.time(), a.report.topic + " time");
  ASSERT_EQ(a.log.channel_names(), b.log.channel_names());
  for (const std::string& c : a.log.channel_names()) {
    expect_close(a.log.values(c), b.log.values(c), a.report.topic + " " + c);
  }
}

void expect_same_bag(const FileLog& a, const FileLog& b) {
  expect_same_topic(a, b);
  ASSERT_EQ(a.more.size(), b.more.size());
  for (std::size_t i = 0; i < a.more.size(); ++i) expect_same_topic(a.more[i], b.more[i]);
}

TEST(ReadDb3Bag, GivesTheColumnsOfTheMcapOfTheSameMessages) {
  const TempDir dir;
  const Bag bag = vessel_bag();
  write_mcap(bag, dir / "vessel.mcap");
  write_db3(bag, dir / "legacy.db3", false);
  write_db3(bag, dir / "iron.db3", true);
  const ColumnMap map = vessel_map();
  const FileLog mcap = read_bag_file(dir / "vessel.mcap", map, BagTime::kAuto);
  const FileLog legacy = read_db3_bag(dir / "legacy.db3", map, BagTime::kAuto);
  const FileLog iron = read_db3_bag(dir / "iron.db3", map, BagTime::kAuto);
  expect_same_bag(legacy, mcap);
  expect_same_bag(iron, mcap);
  EXPECT_EQ(legacy.report.format, "db3");
  EXPECT_EQ(mcap.report.format, "mcap");
  // And the truth: the axis topic's stamps (header, 3 ms before each 0.1 s), one repeat dropped.
  EXPECT_EQ(legacy.report.topic, "/imu");
  EXPECT_EQ(legacy.report.time_format, "header.stamp");
  EXPECT_EQ(*legacy.origin_ns, kStart - 3'000'000);
  ASSERT_EQ(legacy.log.size(), 50U);
  EXPECT_EQ(legacy.report.skipped.count("repeated time"), 1U);
  for (std::size_t k = 0; k < 50; ++k) {
    EXPECT_NEAR(legacy.log.time()[k], 0.1 * static_cast<double>(k), 1e-9);
    EXPECT_DOUBLE_EQ(legacy.log.values("output")[k], 1.0 / (1.0 + 0.1 * static_cast<double>(k)));
  }
  const auto topic = [&](const std::string& name) -> const FileLog& {
    for (const FileLog& f : legacy.more) {
      if (f.report.topic == name) return f;
    }
    throw std::runtime_error("no topic " + name);
  };
  EXPECT_EQ(topic("/cmd").report.time_format, "receive time");
  EXPECT_EQ(topic("/fix").log.size(), 10U);
  EXPECT_DOUBLE_EQ(topic("/fix").log.values("lat")[3], (63.4 + 15e-6) * M_PI / 180.0);  // SI
  EXPECT_DOUBLE_EQ(topic("/odom").log.values("east")[4], 1e-3 * 5 * 36);
  EXPECT_TRUE(std::isnan(topic("/joints").log.values("q")[0]));
}

TEST(ReadDb3Bag, GivesTheColumnsOfACsvOfTheSameNumbers) {
  const TempDir dir;
  const Bag bag = vessel_bag();
  write_db3(bag, dir / "vessel.db3", false);
  // The /odom numbers as CSV, time stamps in epoch nanoseconds.
  std::string csv = "time,north,u\n";
  for (int k = 0; k < 50; ++k) {
    const double x = 0.1 * k;
    csv +=
        fmt::format("{},{},{}\n", kStart + 100'000'000LL * k + 5'000'000, 100.0 + x, 2.5 + x * x);
  }
  const auto csv_path = dir.write("odom.csv", csv);
  ColumnMap csv_map;
  csv_map.set_column("time", "time");
  csv_map.set_column("north", "north");
  csv_map.set_column("u", "u");
  apply_time_overrides(csv_map, "epoch-ns", "", "");
  const FileLog from_csv = read_log_file(csv_path, csv_map);
  ColumnMap bag_map;
  bag_map.set_column("time", "time");
  bag_map.set_column("north", "/odom.pose.pose.position.x");
  bag_map.set_column("u", "/odom.twist.twist.linear.x");
  const FileLog from_bag = read_log_file(dir / "vessel.db3", bag_map);
  EXPECT_EQ(from_bag.report.format, "db3");
  EXPECT_EQ(from_bag.origin_ns, from_csv.origin_ns);
  expect_close(from_bag.log.time(), from_csv.log.time(), "time");
  expect_close(from_bag.log.values("north"), from_csv.log.values("north"), "north");
  expect_close(from_bag.log.values("u"), from_csv.log.values("u"), "u");
}

TEST(ReadDb3Bag, ReadsABagFolderOfSeveralFiles) {
  const TempDir dir;
  const Bag bag = vessel_bag();
  write_db3(bag, dir / "whole.db3", false);
  // The same messages split in two files, each with its own topic ids.
  std::filesystem::create_directory(dir / "split");
  {
    Db3Writer a(dir / "split" / "split_0.db3");
    Db3Writer b(dir / "split" / "split_1.db3");
    for (std::size_t i = 0; i < bag.topics.size(); ++i) {
      a.topic(static_cast<std::int64_t>(i + 1), bag.topics[i].name, bag.topics[i].type);
      b.topic(static_cast<std::int64_t>(20 - i), bag.topics[i].name, bag.topics[i].type);
    }
    for (std::size_t m = 0; m < bag.messages.size(); ++m) {
      const Message& msg = bag.messages[m];
      if (m < bag.messages.size() / 2) {
        a.message(static_cast<std::int64_t>(msg.topic + 1), msg.receive_ns, msg.data);
      } else {
        b.message(static_cast<std::int64_t>(20 - msg.topic), msg.receive_ns, msg.data);
      }
    }
  }
  dir.write("split/metadata.yaml",
            "rosbag2_bagfile_information:\n  version: 5\n  storage_identifier: sqlite3\n"
            "  relative_file_paths:\n    - split_0.db3\n    - \"split_1.db3\"\n"
            "  compression_format: \"\"\n  compression_mode: \"\"\n");
  EXPECT_TRUE(looks_like_db3(dir / "split"));
  EXPECT_TRUE(looks_like_db3(dir / "whole.db3"));
  const ColumnMap map = vessel_map();
  expect_same_bag(read_log_file(dir / "split", map),
                  read_db3_bag(dir / "whole.db3", map, BagTime::kAuto));
  // A listed file that is missing.
  dir.write("split/metadata.yaml",
            "rosbag2_bagfile_information:\n  relative_file_paths:\n    - split_0.db3\n"
            "    - split_9.db3\n");
  EXPECT_THAT(input_error_message([&] { (void)read_db3_bag(dir / "split", map, BagTime::kAuto); }),
              HasSubstr("the bag's file 'split_9.db3' is missing"));
}

TEST(ReadDb3Bag, TakesTypesFromTheMsgPathFoldersAndTheBagsDefinitions) {
  const TempDir dir;
  // acme_msgs/msg/Thrust nests a type of its package (a file by its name only) and built-in
  // ones.
  std::filesystem::create_directories(dir / "msgs" / "acme_msgs" / "msg");
  dir.write("msgs/acme_msgs/msg/Thrust.msg",
            "# thrust of one unit\nHeader header\nUnitState state\n"
            "geometry_msgs/Vector3 force  # [N]\nfloat32[<=4] blades\n");
  dir.write("msgs/UnitState.msg", "uint8 RUNNING=1\nuint8 mode\nfloat64 rpm\n");
  const auto thrust = [](int k) {
    CdrWriter w;
    w.header(kStart + 200'000'000LL * k, "pod").put(std::uint8_t{1}).put(100.0 * k);
    vector3(w, 1000.0 * k, -5.0, 0.0).put(std::uint32_t{1}).put(0.25F);
    return w.bytes();
  };
  {
    Db3Writer w(dir / "acme.db3");
    w.topic(1, "/thrust", "acme_msgs/msg/Thrust");
    for (int k = 0; k < 4; ++k) w.message(1, kStart + 200'000'000LL * k + 1000, thrust(k));
  }
  ColumnMap map;
  map.set_column("time", "time");
  map.set_column("input", "/thrust.state.rpm");
  map.set_column("output", "/thrust.force.x");
  const std::string no_type =
      input_error_message([&] { (void)read_db3_bag(dir / "acme.db3", map, BagTime::kAuto); });
  EXPECT_THAT(no_type, HasSubstr("acme.db3 (/thrust): no definition of the type "
                                 "acme_msgs/msg/Thrust: it is not built in"));
  EXPECT_THAT(no_type, HasSubstr("--msg-path DIR adds it"));
  const FileLog log =
      read_db3_bag(dir / "acme.db3", map, BagTime::kAuto, Ros2MsgSet({dir / "msgs"}));
  EXPECT_EQ(log.report.time_format, "header.stamp");
  EXPECT_EQ(log.log.values("input"), (std::vector<double>{0.0, 100.0, 200.0, 300.0}));
  EXPECT_EQ(log.log.values("output"), (std::vector<double>{0.0, 1000.0, 2000.0, 3000.0}));
  // A nested type missing from the folders is named.
  std::filesystem::remove(dir / "msgs" / "UnitState.msg");
  EXPECT_THAT(input_error_message([&] {
                (void)read_db3_bag(dir / "acme.db3", map, BagTime::kAuto,
                                   Ros2MsgSet({dir / "msgs"}));
              }),
              HasSubstr("no definition of acme_msgs/UnitState"));
  // A bag of rosbag2 since Iron carries the definitions itself.
  {
    Db3Writer w(dir / "iron.db3", true);
    w.topic(1, "/thrust", "acme_msgs/msg/Thrust");
    w.definition("acme_msgs/msg/Thrust", "ros2msg",
                 "std_msgs/Header header\nUnitState state\ngeometry_msgs/Vector3 force\n"
                 "float32[<=4] blades\n" +
                     std::string(80, '=') +
                     "\nMSG: acme_msgs/UnitState\nuint8 mode\nfloat64 rpm\n");
    for (int k = 0; k < 4; ++k) w.message(1, kStart + 200'000'000LL * k + 1000, thrust(k));
  }
  EXPECT_EQ(read_db3_bag(dir / "iron.db3", map, BagTime::kReceive).log.values("output"),
            (std::vector<double>{0.0, 1000.0, 2000.0, 3000.0}));
}

TEST(ReadDb3Bag, NamesTheFileMessageAndTopicOfABadBag) {
  const TempDir dir;
  ColumnMap map;
  map.set_column("time", "time");
  map.set_column("input", "/cmd.data");
  const auto message = [&](const std::filesystem::path& path) {
    return input_error_message([&] { (void)read_db3_bag(path, map, BagTime::kAuto); });
  };
  EXPECT_THAT(message(dir.write("text.db3", "time,cmd\n0,1\n")),
              HasSubstr("text.db3: not an SQLite database"));
  {
    Db3Writer w(dir / "other.db3");
    w.exec("DROP TABLE messages; CREATE TABLE readings(x REAL)");
  }
  EXPECT_THAT(message(dir / "other.db3"),
              HasSubstr("other.db3: not a rosbag2 bag: it has no table 'messages' (its tables: "
                        "readings, topics)"));
  {
    Db3Writer w(dir / "short.db3");
    w.topic(3, "/cmd", "std_msgs/msg/Float64");
    w.message(3, kStart, CdrWriter().put(1.0).bytes());
    w.message(3, kStart + 1, Bytes{0x00, 0x01, 0x00, 0x00, 0x01, 0x02});
  }
  EXPECT_THAT(message(dir / "short.db3"),
              HasSubstr("short.db3 (/cmd): at message id 2: the message: "));
  {
    Db3Writer w(dir / "json.db3");
    w.topic(1, "/cmd", "std_msgs/msg/Float64", "json");
    w.message(1, kStart, Bytes{'{', '}'});
  }
  EXPECT_THAT(message(dir / "json.db3"),
              HasSubstr("json.db3 (/cmd): the topic's serialization format is 'json'"));
  {
    Db3Writer w(dir / "notopic.db3");
    w.topic(1, "/rpm", "std_msgs/msg/Float64");
  }
  EXPECT_THAT(message(dir / "notopic.db3"),
              HasSubstr("notopic.db3 (/cmd): the bag has no topic '/cmd' (role 'input'); its "
                        "topics: /rpm"));
  map.set_column("input", "/cmd.dta");
  EXPECT_THAT(message(dir / "short.db3"), HasSubstr("'dta': std_msgs/Float64 has no field 'dta'"));
  // A type the bag holds as IDL only, and that is not built in.
  {
    Db3Writer w(dir / "idl.db3", true);
    w.topic(1, "/cmd", "acme_msgs/msg/Cmd");
    w.definition("acme_msgs/msg/Cmd", "ros2idl", "module acme_msgs { };");
  }
  EXPECT_THAT(message(dir / "idl.db3"),
              HasSubstr("no definition of the type acme_msgs/msg/Cmd (the bag holds it as "
                        "'ros2idl', not ros2msg): it is not built in"));
}

TEST(Ros2MsgSet, EveryBuiltInTypeResolvesAndFoldersComeFirst) {
  const Ros2MsgSet builtin;
  for (const std::string& type : ros2_builtin_msg_types()) {
    EXPECT_NO_THROW((void)builtin.schema(type)) << type;
  }
  EXPECT_EQ(builtin.schema("sensor_msgs/msg/Imu").types[0].fields.size(), 7U);
  EXPECT_EQ(builtin.schema("sensor_msgs/msg/NavSatFix").types[0].fields.size(), 7U);
  const TempDir dir;
  std::filesystem::create_directories(dir / "a" / "std_msgs" / "msg");
  dir.write("a/std_msgs/msg/Float64.msg", "float32 data\n");
  dir.write("a/Float64.msg", "int8 data\n");
  std::filesystem::create_directories(dir / "b");
  dir.write("b/Float64.msg", "int16 data\n");
  const Ros2MsgSet set({dir / "b", dir / "a"});
  EXPECT_EQ(set.find("std_msgs/msg/Float64"), "int16 data\n");
  EXPECT_EQ(Ros2MsgSet({dir / "a"}).find("std_msgs/Float64"), "float32 data\n");
  EXPECT_EQ(Ros2MsgSet({dir / "a"}).find("other_msgs/Float64"), "int8 data\n");
  EXPECT_EQ(builtin.find("std_msgs/Float64"), "float64 data\n");
  EXPECT_EQ(builtin.find("acme_msgs/Thing"), std::nullopt);
}

}  // namespace
}  // namespace dynpos::io
