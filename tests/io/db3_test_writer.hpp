#pragma once
// A small writer of rosbag2 SQLite bags (.db3) for the tests' own fixtures, on the SQLite C API
// (not part of dynpos): the tables rosbag2 creates, and message_definitions when asked.

#include <sqlite3.h>

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace dynpos::io::testing {

class Db3Writer {
 public:
  /// A new bag at `path` (replaced); with `definitions`, the table of rosbag2 since Iron.
  explicit Db3Writer(const std::filesystem::path& path, bool definitions = false) {
    std::filesystem::remove(path);
    if (sqlite3_open(path.c_str(), &db_) != SQLITE_OK) fail("open");
    exec(
        "CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT NULL, "
        "serialization_format TEXT NOT NULL, offered_qos_profiles TEXT NOT NULL);"
        "CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id INTEGER NOT NULL, "
        "timestamp INTEGER NOT NULL, data BLOB NOT NULL);"
        "CREATE INDEX timestamp_idx ON messages (timestamp ASC);");
    if (definitions) {
      exec(
          "CREATE TABLE message_definitions(id INTEGER PRIMARY KEY, topic_type TEXT NOT NULL, "
          "encoding TEXT NOT NULL, encoded_message_definition TEXT NOT NULL, "
          "type_description_hash TEXT NOT NULL);");
    }
    exec("BEGIN");
  }
  ~Db3Writer() {
    sqlite3_exec(db_, "COMMIT", nullptr, nullptr, nullptr);
    sqlite3_close(db_);
  }
  Db3Writer(const Db3Writer&) = delete;
  Db3Writer& operator=(const Db3Writer&) = delete;

  void exec(const std::string& sql) {
    if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, nullptr) != SQLITE_OK) fail(sql);
  }

  void topic(std::int64_t id, const std::string& name, const std::string& type,
             const std::string& format = "cdr") {
    run("INSERT INTO topics VALUES (?, ?, ?, ?, '')", [&](sqlite3_stmt* s) {
      sqlite3_bind_int64(s, 1, id);
      text(s, 2, name);
      text(s, 3, type);
      text(s, 4, format);
    });
  }
  void definition(const std::string& type, const std::string& encoding, const std::string& def) {
    run("INSERT INTO message_definitions(topic_type, encoding, encoded_message_definition, "
        "type_description_hash) VALUES (?, ?, ?, '')",
        [&](sqlite3_stmt* s) {
          text(s, 1, type);
          text(s, 2, encoding);
          text(s, 3, def);
        });
  }
  void message(std::int64_t topic_id, std::int64_t timestamp_ns,
               const std::vector<std::uint8_t>& data) {
    run("INSERT INTO messages(topic_id, timestamp, data) VALUES (?, ?, ?)", [&](sqlite3_stmt* s) {
      sqlite3_bind_int64(s, 1, topic_id);
      sqlite3_bind_int64(s, 2, timestamp_ns);
      sqlite3_bind_blob(s, 3, data.data(), static_cast<int>(data.size()), SQLITE_TRANSIENT);
    });
  }

 private:
  static void text(sqlite3_stmt* s, int i, const std::string& t) {
    sqlite3_bind_text(s, i, t.c_str(), static_cast<int>(t.size()), SQLITE_TRANSIENT);
  }
  template <class Bind>
  void run(const char* sql, Bind&& bind) {
    sqlite3_stmt* s = nullptr;
    if (sqlite3_prepare_v2(db_, sql, -1, &s, nullptr) != SQLITE_OK) fail(sql);
    bind(s);
    const int rc = sqlite3_step(s);
    sqlite3_finalize(s);
    if (rc != SQLITE_DONE) fail(sql);
  }
  [[noreturn]] void fail(const std::string& what) {
    throw std::runtime_error("test bag: " + what + ": " + sqlite3_errmsg(db_));
  }
  sqlite3* db_ = nullptr;
};

}  // namespace dynpos::io::testing
