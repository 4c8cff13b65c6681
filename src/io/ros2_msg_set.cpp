#include "dynpos/io/ros2_msg_set.hpp"

#include <algorithm>
#include <array>
#include <fstream>
#include <iterator>
#include <system_error>

#include <fmt/format.h>

namespace dynpos::io {
namespace {

struct BuiltinMsg {
  std::string_view type;
  std::string_view text;
};

// The field lists of the common types, as their packages define them (constants only where a
// field's values are coded).
constexpr std::array<BuiltinMsg, 67> kBuiltin = {{
    {"builtin_interfaces/Duration", "int32 sec\nuint32 nanosec\n"},
    {"builtin_interfaces/Time", "int32 sec\nuint32 nanosec\n"},
    {"geometry_msgs/Accel", "Vector3 linear\nVector3 angular\n"},
    {"geometry_msgs/AccelStamped", "std_msgs/Header header\nAccel accel\n"},
    {"geometry_msgs/AccelWithCovariance", "Accel accel\nfloat64[36] covariance\n"},
    {"geometry_msgs/AccelWithCovarianceStamped",
     "std_msgs/Header header\nAccelWithCovariance accel\n"},
    {"geometry_msgs/Inertia",
     "float64 m\nVector3 com\nfloat64 ixx\nfloat64 ixy\nfloat64 ixz\nfloat64 iyy\nfloat64 iyz\n"
     "float64 izz\n"},
    {"geometry_msgs/InertiaStamped", "std_msgs/Header header\nInertia inertia\n"},
    {"geometry_msgs/Point", "float64 x\nfloat64 y\nfloat64 z\n"},
    {"geometry_msgs/Point32", "float32 x\nfloat32 y\nfloat32 z\n"},
    {"geometry_msgs/PointStamped", "std_msgs/Header header\nPoint point\n"},
    {"geometry_msgs/Polygon", "Point32[] points\n"},
    {"geometry_msgs/PolygonStamped", "std_msgs/Header header\nPolygon polygon\n"},
    {"geometry_msgs/Pose", "Point position\nQuaternion orientation\n"},
    {"geometry_msgs/Pose2D", "float64 x\nfloat64 y\nfloat64 theta\n"},
    {"geometry_msgs/PoseArray", "std_msgs/Header header\nPose[] poses\n"},
    {"geometry_msgs/PoseStamped", "std_msgs/Header header\nPose pose\n"},
    {"geometry_msgs/PoseWithCovariance", "Pose pose\nfloat64[36] covariance\n"},
    {"geometry_msgs/PoseWithCovarianceStamped",
     "std_msgs/Header header\nPoseWithCovariance pose\n"},
    {"geometry_msgs/Quaternion", "float64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n"},
    {"geometry_msgs/QuaternionStamped", "std_msgs/Header header\nQuaternion quaternion\n"},
    {"geometry_msgs/Transform", "Vector3 translation\nQuaternion rotation\n"},
    {"geometry_msgs/TransformStamped",
     "std_msgs/Header header\nstring child_frame_id\nTransform transform\n"},
    {"geometry_msgs/Twist", "Vector3 linear\nVector3 angular\n"},
    {"geometry_msgs/TwistStamped", "std_msgs/Header header\nTwist twist\n"},
    {"geometry_msgs/TwistWithCovariance", "Twist twist\nfloat64[36] covariance\n"},
    {"geometry_msgs/TwistWithCovarianceStamped",
     "std_msgs/Header header\nTwistWithCovariance twist\n"},
    {"geometry_msgs/Vector3", "float64 x\nfloat64 y\nfloat64 z\n"},
    {"geometry_msgs/Vector3Stamped", "std_msgs/Header header\nVector3 vector\n"},
    {"geometry_msgs/Wrench", "Vector3 force\nVector3 torque\n"},
    {"geometry_msgs/WrenchStamped", "std_msgs/Header header\nWrench wrench\n"},
    {"nav_msgs/Odometry",
     "std_msgs/Header header\nstring child_frame_id\ngeometry_msgs/PoseWithCovariance pose\n"
     "geometry_msgs/TwistWithCovariance twist\n"},
    {"sensor_msgs/FluidPressure",
     "std_msgs/Header header\nfloat64 fluid_pressure\nfloat64 variance\n"},
    {"sensor_msgs/Imu",
     "std_msgs/Header header\ngeometry_msgs/Quaternion orientation\n"
     "float64[9] orientation_covariance\ngeometry_msgs/Vector3 angular_velocity\n"
     "float64[9] angular_velocity_covariance\ngeometry_msgs/Vector3 linear_acceleration\n"
     "float64[9] linear_acceleration_covariance\n"},
    {"sensor_msgs/JointState",
     "std_msgs/Header header\nstring[] name\nfloat64[] position\nfloat64[] velocity\n"
     "float64[] effort\n"},
    {"sensor_msgs/Joy", "std_msgs/Header header\nfloat32[] axes\nint32[] buttons\n"},
    {"sensor_msgs/MagneticField",
     "std_msgs/Header header\ngeometry_msgs/Vector3 magnetic_field\n"
     "float64[9] magnetic_field_covariance\n"},
    {"sensor_msgs/NavSatFix",
     "uint8 COVARIANCE_TYPE_UNKNOWN=0\nuint8 COVARIANCE_TYPE_APPROXIMATED=1\n"
     "uint8 COVARIANCE_TYPE_DIAGONAL_KNOWN=2\nuint8 COVARIANCE_TYPE_KNOWN=3\n"
     "std_msgs/Header header\nNavSatStatus status\nfloat64 latitude  # degrees\n"
     "float64 longitude  # degrees\nfloat64 altitude  # metres above the WGS84 ellipsoid\n"
     "float64[9] position_covariance\nuint8 position_covariance_type\n"},
    {"sensor_msgs/NavSatStatus",
     "int8 STATUS_NO_FIX=-1\nint8 STATUS_FIX=0\nint8 STATUS_SBAS_FIX=1\nint8 STATUS_GBAS_FIX=2\n"
     "int8 status\nuint16 SERVICE_GPS=1\nuint16 SERVICE_GLONASS=2\nuint16 SERVICE_COMPASS=4\n"
     "uint16 SERVICE_GALILEO=8\nuint16 service\n"},
    {"sensor_msgs/RelativeHumidity",
     "std_msgs/Header header\nfloat64 relative_humidity\nfloat64 variance\n"},
    {"sensor_msgs/Temperature", "std_msgs/Header header\nfloat64 temperature\nfloat64 variance\n"},
    {"sensor_msgs/TimeReference",
     "std_msgs/Header header\nbuiltin_interfaces/Time time_ref\nstring source\n"},
    {"std_msgs/Bool", "bool data\n"},
    {"std_msgs/Byte", "byte data\n"},
    {"std_msgs/Char", "char data\n"},
    {"std_msgs/ColorRGBA", "float32 r\nfloat32 g\nfloat32 b\nfloat32 a\n"},
    {"std_msgs/Empty", ""},
    {"std_msgs/Float32", "float32 data\n"},
    {"std_msgs/Float32MultiArray", "MultiArrayLayout layout\nfloat32[] data\n"},
    {"std_msgs/Float64", "float64 data\n"},
    {"std_msgs/Float64MultiArray", "MultiArrayLayout layout\nfloat64[] data\n"},
    {"std_msgs/Header", "builtin_interfaces/Time stamp\nstring frame_id\n"},
    {"std_msgs/Int16", "int16 data\n"},
    {"std_msgs/Int32", "int32 data\n"},
    {"std_msgs/Int32MultiArray", "MultiArrayLayout layout\nint32[] data\n"},
    {"std_msgs/Int64", "int64 data\n"},
    {"std_msgs/Int64MultiArray", "MultiArrayLayout layout\nint64[] data\n"},
    {"std_msgs/Int8", "int8 data\n"},
    {"std_msgs/MultiArrayDimension", "string label\nuint32 size\nuint32 stride\n"},
    {"std_msgs/MultiArrayLayout", "MultiArrayDimension[] dim\nuint32 data_offset\n"},
    {"std_msgs/String", "string data\n"},
    {"std_msgs/UInt16", "uint16 data\n"},
    {"std_msgs/UInt32", "uint32 data\n"},
    {"std_msgs/UInt64", "uint64 data\n"},
    {"std_msgs/UInt8", "uint8 data\n"},
    {"std_msgs/UInt8MultiArray", "MultiArrayLayout layout\nuint8[] data\n"},
    {"std_msgs/UInt32MultiArray", "MultiArrayLayout layout\nuint32[] data\n"},
}};

std::optional<std::string> builtin_text(std::string_view type) {
  for (const BuiltinMsg& m : kBuiltin) {
    if (m.type == type) return std::string(m.text);
  }
  return std::nullopt;
}

// The text of the file `path`, or nullopt when there is none.
std::optional<std::string> read_msg_file(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  const std::uintmax_t bytes = std::filesystem::file_size(path, ec);
  if (ec || bytes > kMaxMsgFileBytes) {
    throw Ros2MsgError(fmt::format("{}: {}", path.string(),
                                   ec ? ec.message()
                                      : fmt::format("{} bytes, more than a message definition "
                                                    "({} at most)",
                                                    bytes, kMaxMsgFileBytes)));
  }
  std::ifstream in(path, std::ios::binary);
  std::string text(static_cast<std::size_t>(bytes), '\0');
  if (!in.read(text.data(), static_cast<std::streamsize>(bytes))) {
    throw Ros2MsgError(fmt::format("{}: cannot be read", path.string()));
  }
  return text;
}

}  // namespace

std::vector<std::string> ros2_builtin_msg_types() {
  std::vector<std::string> out;
  for (const BuiltinMsg& m : kBuiltin) out.emplace_back(m.type);
  std::sort(out.begin(), out.end());
  return out;
}

Ros2MsgSet::Ros2MsgSet(std::vector<std::filesystem::path> folders) : folders_(std::move(folders)) {}

std::optional<std::string> Ros2MsgSet::find(std::string_view type) const {
  const std::string name = ros2_type_name(type);
  const auto slash = name.find('/');
  const std::string package = slash == std::string::npos ? std::string() : name.substr(0, slash);
  const std::string base = name.substr(slash == std::string::npos ? 0 : slash + 1);
  if (!base.empty() && base.find('/') == std::string::npos && base != "." && base != "..") {
    for (const std::filesystem::path& dir : folders_) {
      if (!package.empty()) {
        if (auto text = read_msg_file(dir / package / "msg" / (base + ".msg"))) return text;
      }
      if (auto text = read_msg_file(dir / (base + ".msg"))) return text;
    }
  }
  return builtin_text(name);
}

Ros2MsgLookup Ros2MsgSet::lookup() const {
  return [this](const std::string& type) { return find(type); };
}

Ros2Schema Ros2MsgSet::schema(std::string_view type) const {
  const std::optional<std::string> text = find(type);
  if (!text) {
    throw Ros2MsgError(
        fmt::format("no definition of {} (not built in, not in the --msg-path "
                    "folders)",
                    ros2_type_name(type)));
  }
  return Ros2Schema::parse(type, *text, lookup());
}

}  // namespace dynpos::io
