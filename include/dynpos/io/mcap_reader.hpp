#pragma once
/// \file
/// McapReader: the messages of an MCAP file (the container of ROS 2 bags), streamed chunk by
/// chunk, without ROS.
///
/// Records read: Header, Schema, Channel, Message, Chunk (compression "", "lz4" (frame) or
/// "zstd"; its uncompressed CRC checked when not 0), ChunkIndex, Statistics (its messages per
/// channel, as a hint), the summary section and the Footer; MessageIndex, Attachment, Metadata
/// and the other index records are skipped. With a summary holding chunk indexes, only the chunks
/// that hold a wanted channel are read, in file order; without (a file cut short, an unindexed
/// writer), the file is read from its start to DataEnd or its end. Chunks are read (pread),
/// decompressed and their CRC checked on worker threads ahead of the calling thread (a zstd/LZ4
/// context per thread), which hands their messages on in file order; with a McapChunkWork, the
/// thread that decompressed a chunk also takes its messages ahead (decodes them) and the calling
/// thread hands on what it took, then the chunk's other messages. The messages, their order and the
/// errors do not depend on the number of threads (the first error in file order is the one thrown).
/// Memory: at most two chunks per thread and one more in flight (compressed, decompressed and what
/// the work took of them; within 64 MiB of compressed bytes read ahead beyond the first), each at
/// most kMaxMcapChunkBytes; never the whole file.
///
/// Every size a record declares is checked against the bytes left before anything is
/// allocated: a bad file is a core::InputError naming the file, the byte offset of the record
/// (and inside a chunk, of the record in its decompressed bytes) and the topic when known.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "dynpos/core/error.hpp"

namespace dynpos::io {

/// The largest chunk (compressed or not) and the largest unchunked message [bytes]: 256 MiB.
inline constexpr std::uint64_t kMaxMcapChunkBytes = std::uint64_t{256} << 20;

/// Whether `path` starts with the MCAP magic "\x89MCAP0\r\n".
bool looks_like_mcap(const std::filesystem::path& path);

struct McapSchema {
  std::uint16_t id = 0;
  std::string name;      ///< e.g. "sensor_msgs/msg/Imu"
  std::string encoding;  ///< e.g. "ros2msg"
  std::string data;      ///< the definition text
};

struct McapChannel {
  std::uint16_t id = 0;
  std::uint16_t schema_id = 0;
  std::string topic;             ///< e.g. "/imu"
  std::string message_encoding;  ///< e.g. "cdr"
};

/// One message, valid during the callback only.
struct McapMessage {
  std::uint16_t channel_id = 0;
  std::uint64_t log_time_ns = 0;      ///< receive time [ns]
  std::uint64_t publish_time_ns = 0;  ///< [ns]
  std::span<const std::uint8_t> data;
  std::uint64_t record_offset = 0;  ///< the byte offset of its record in the file, or its chunk's
  /// Inside a chunk: the byte offset of its record in the chunk's decompressed records.
  std::optional<std::uint64_t> offset_in_chunk;

  /// "byte 1234" or "byte 56 of the records of the chunk at byte 1234", for messages.
  std::string position() const;
};

/// Work on the messages of a chunk done ahead of the calling thread, on the thread that
/// decompressed the chunk (a worker, or the calling thread when no worker took it): e.g. the
/// messages decoded into per-chunk columns, which the calling thread appends in file order.
/// McapReader::read_messages makes one per chunk in flight and uses it again for later chunks.
class McapChunkWork {
 public:
  virtual ~McapChunkWork() = default;
  /// On the calling thread, as the chunk is queued: keeps what take() needs, which must not
  /// change while the chunk is in flight.
  virtual void prepare() = 0;
  /// On the chunk's thread, for its messages of channels known wanted when the chunk was queued,
  /// in file order: takes the message (true) or leaves it with no trace (false); that message
  /// and every one after it in the chunk then go to on_message on the calling thread.
  virtual bool take(const McapMessage& message) = 0;
  /// On the calling thread, as the chunk comes in file order, before its messages left go to
  /// on_message: hands on what take() took.
  virtual void hand_on() = 0;
};

class McapReader {
 public:
  /// Opens `path`: checks the magic and reads the summary section when the footer points to
  /// one. Chunks are decompressed on `jobs` worker threads (0 = every core; 1 = none: all on
  /// the calling thread). Throws core::InputError for a file that cannot be read or is not MCAP.
  explicit McapReader(const std::filesystem::path& path, unsigned jobs = 0);
  ~McapReader();
  McapReader(const McapReader&) = delete;
  McapReader& operator=(const McapReader&) = delete;
  McapReader(McapReader&&) noexcept;
  McapReader& operator=(McapReader&&) noexcept;

  /// The schemas and channels known so far: all of them after the constructor when the file
  /// has a summary, else those read so far (a channel's record comes before its messages).
  const std::map<std::uint16_t, McapSchema>& schemas() const noexcept;
  const std::map<std::uint16_t, McapChannel>& channels() const noexcept;
  /// Whether the summary section listed the schemas and channels (so channels() is complete).
  bool has_summary() const noexcept;
  /// The messages per channel id that the summary's Statistics record declares (empty without
  /// one, or when it is damaged): a hint for reserving room, never checked against the messages.
  const std::map<std::uint16_t, std::uint64_t>& message_counts() const noexcept;

  /// Calls on_message for every message of a channel that `wanted` accepts (asked once per
  /// channel, when it is first known), in file order. Throws core::InputError for a bad record.
  void read_messages(const std::function<bool(const McapChannel&)>& wanted,
                     const std::function<void(const McapMessage&)>& on_message);
  /// The same, with work made by `chunk_work` taking messages of chunks ahead (McapChunkWork):
  /// every message is still seen once, by take() or by on_message, in file order. A chunk's
  /// messages are offered to take() up to its first Schema or Channel record, message of a
  /// channel whose wish is not known yet, or bad record, which the calling thread meets in turn.
  void read_messages(const std::function<bool(const McapChannel&)>& wanted,
                     const std::function<void(const McapMessage&)>& on_message,
                     const std::function<std::unique_ptr<McapChunkWork>()>& chunk_work);

  /// An error of this file at `where` (e.g. McapMessage::position()), naming `topic` if any.
  core::InputError error(const std::string& where, const std::string& problem,
                         const std::string& topic = {}, const std::string& hint = {}) const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace dynpos::io
