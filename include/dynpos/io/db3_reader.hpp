#pragma once
/// \file
/// Db3Reader: the topics, message definitions and messages of a rosbag2 SQLite bag (`.db3`,
/// the default storage of ROS 2 before Iron), without ROS.
///
/// A bag is a .db3 file, or a folder with metadata.yaml and the .db3 files it lists
/// (relative_file_paths; without such a list, its *.db3 files by name). Each file is opened
/// read-only and immutable (never written, no journal looked for) and is read by its tables
/// `topics` (id, name, type, serialization_format), `messages` (id, topic_id, timestamp, data)
/// and, when present (rosbag2 since Iron), `message_definitions` (topic_type, encoding,
/// encoded_message_definition). Messages are queried by topic and streamed in timestamp order,
/// one row at a time; a message's bytes are valid during its callback only.
///
/// A bad bag is a core::InputError naming the file, the message id and the topic when known.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "dynpos/core/error.hpp"

namespace dynpos::io {

/// The largest message read [bytes]: 256 MiB (the limit of an MCAP chunk).
inline constexpr int kMaxDb3MessageBytes = 256 << 20;

/// Whether `path` is a rosbag2 SQLite bag: a file that starts with "SQLite format 3\0", or a
/// folder holding metadata.yaml and a .db3 file.
bool looks_like_db3(const std::filesystem::path& path);

/// The .db3 files of the bag `path` (db3_reader.hpp above). Throws core::InputError for a folder
/// without metadata.yaml or .db3 files, a listed file that is missing, and a bag of another
/// storage or compressed.
std::vector<std::filesystem::path> db3_files(const std::filesystem::path& path);

struct Db3Topic {
  std::int64_t id = 0;
  std::string name;                  ///< e.g. "/imu"
  std::string type;                  ///< e.g. "sensor_msgs/msg/Imu"
  std::string serialization_format;  ///< e.g. "cdr"
};

struct Db3Definition {
  std::string encoding;  ///< "ros2msg", "ros2idl" or "unknown"
  std::string text;      ///< the definition (empty when the recorder did not find it)
};

/// One message, valid during the callback only.
struct Db3Message {
  std::int64_t id = 0;
  std::int64_t topic_id = 0;
  std::int64_t timestamp_ns = 0;  ///< receive time [ns since 1970]
  std::span<const std::uint8_t> data;
};

/// One .db3 file.
class Db3Reader {
 public:
  /// Opens `file` (named `name` in errors) and reads its topics and definitions. Throws
  /// core::InputError for a file that cannot be read, is not SQLite or lacks the tables.
  Db3Reader(const std::filesystem::path& file, std::string name);
  ~Db3Reader();
  Db3Reader(const Db3Reader&) = delete;
  Db3Reader& operator=(const Db3Reader&) = delete;
  Db3Reader(Db3Reader&&) noexcept;
  Db3Reader& operator=(Db3Reader&&) noexcept;

  const std::vector<Db3Topic>& topics() const noexcept;
  /// The definitions the file stores, by type ("pkg/msg/Type"); empty before rosbag2 Iron.
  const std::map<std::string, Db3Definition>& definitions() const noexcept;

  /// Calls on_message for every message of the topics `topic_ids`, in timestamp order. Throws
  /// core::InputError for a damaged file (naming the last message read).
  void read_messages(const std::vector<std::int64_t>& topic_ids,
                     const std::function<void(const Db3Message&)>& on_message);

  /// An error of this file at `where` (e.g. "message id 12"), naming `topic` if any.
  core::InputError error(const std::string& where, const std::string& problem,
                         const std::string& topic = {}, const std::string& hint = {}) const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace dynpos::io
