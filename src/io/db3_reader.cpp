#include "dynpos/io/db3_reader.hpp"

#include <sqlite3.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "text_util.hpp"

namespace dynpos::io {
namespace {

constexpr std::array<char, 16> kSqliteMagic = {'S', 'Q', 'L', 'i', 't', 'e', ' ', 'f',
                                               'o', 'r', 'm', 'a', 't', ' ', '3', '\0'};
constexpr std::uintmax_t kMaxMetadataBytes = std::uintmax_t{1} << 20;
constexpr std::string_view kDb3Hint =
    "a rosbag2 SQLite bag has the tables topics and messages (docs/log-format.md, \"ROS 2 bags\")";

bool has_sqlite_magic(const std::filesystem::path& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr) return false;
  std::array<char, 16> head{};
  const bool magic =
      std::fread(head.data(), 1, head.size(), f) == head.size() && head == kSqliteMagic;
  std::fclose(f);
  return magic;
}

// "file:PATH?immutable=1", the path percent-encoded as SQLite's URIs want.
std::string immutable_uri(const std::filesystem::path& path) {
  std::string uri = "file:";
  for (const char c : path.string()) {
    const auto u = static_cast<unsigned char>(c);
    const bool plain = (u >= 'a' && u <= 'z') || (u >= 'A' && u <= 'Z') || (u >= '0' && u <= '9') ||
                       c == '/' || c == '.' || c == '-' || c == '_' || c == '~';
    uri += plain ? std::string(1, c) : fmt::format("%{:02X}", u);
  }
  return uri + "?immutable=1";
}

std::string unquoted(std::string_view s) {
  s = detail::trim(s);
  if (s.size() >= 2 && (s.front() == '"' || s.front() == '\'') && s.back() == s.front()) {
    s = s.substr(1, s.size() - 2);
  }
  return std::string(s);
}

// What dynpos needs of a bag folder's metadata.yaml (rosbag2 writes it in block style).
struct BagMetadata {
  std::string storage;             // storage_identifier
  std::string compression;         // compression_format, empty when none
  std::vector<std::string> files;  // relative_file_paths
};

BagMetadata read_metadata(const std::filesystem::path& file) {
  std::error_code ec;
  const std::uintmax_t bytes = std::filesystem::file_size(file, ec);
  if (ec || bytes > kMaxMetadataBytes) {
    throw core::InputError(
        {file.string(), {}, {}, {}},
        ec ? ec.message() : fmt::format("{} bytes: not the metadata.yaml of a bag", bytes));
  }
  std::ifstream in(file);
  BagMetadata out;
  std::string line;
  bool in_files = false;
  while (std::getline(in, line)) {
    const std::string_view text = detail::trim(line);
    if (in_files && text.starts_with("- ")) {
      out.files.push_back(unquoted(text.substr(2)));
      continue;
    }
    in_files = false;
    const auto colon = text.find(':');
    if (colon == std::string_view::npos) continue;
    const std::string_view key = text.substr(0, colon);
    const std::string value = unquoted(text.substr(colon + 1));
    if (key == "storage_identifier") out.storage = value;
    if (key == "compression_format") out.compression = value;
    if (key == "relative_file_paths") in_files = value.empty();
  }
  return out;
}

// A statement, finalised with its scope.
struct Statement {
  Statement() = default;
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;
  ~Statement() { sqlite3_finalize(stmt); }
  sqlite3_stmt* stmt = nullptr;
};

std::string column_text(sqlite3_stmt* stmt, int column) {
  const unsigned char* text = sqlite3_column_text(stmt, column);
  return text == nullptr
             ? std::string()
             : std::string(reinterpret_cast<const char*>(text),
                           static_cast<std::size_t>(sqlite3_column_bytes(stmt, column)));
}

}  // namespace

bool looks_like_db3(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_directory(path, ec)) return has_sqlite_magic(path);
  if (!std::filesystem::is_regular_file(path / "metadata.yaml", ec)) return false;
  for (const auto& entry : std::filesystem::directory_iterator(path, ec)) {
    if (entry.path().extension() == ".db3") return true;
  }
  return false;
}

std::vector<std::filesystem::path> db3_files(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_directory(path, ec)) return {path};
  const std::filesystem::path yaml = path / "metadata.yaml";
  const std::string name = path.string();
  if (!std::filesystem::is_regular_file(yaml, ec)) {
    throw core::InputError({name, {}, {}, {}}, "a folder without metadata.yaml",
                           "a bag folder holds metadata.yaml and its .db3 files");
  }
  const BagMetadata meta = read_metadata(yaml);
  if (!meta.storage.empty() && meta.storage != "sqlite3") {
    throw core::InputError({yaml.string(), {}, {}, {}},
                           fmt::format("the bag's storage is '{}', not sqlite3", meta.storage),
                           "give an MCAP bag's .mcap file itself");
  }
  if (!meta.compression.empty()) {
    throw core::InputError({yaml.string(), {}, {}, {}},
                           fmt::format("the bag is compressed ({})", meta.compression),
                           "dynpos reads uncompressed SQLite bags; decompress it with "
                           "ros2 bag convert");
  }
  std::vector<std::filesystem::path> files;
  for (const std::string& f : meta.files) {
    files.push_back(path / f);
    if (!std::filesystem::is_regular_file(files.back(), ec)) {
      throw core::InputError({yaml.string(), {}, {}, {}},
                             fmt::format("the bag's file '{}' is missing", f));
    }
  }
  if (files.empty()) {
    for (const auto& entry : std::filesystem::directory_iterator(path, ec)) {
      if (entry.path().extension() == ".db3") files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
  }
  if (files.empty()) {
    throw core::InputError({name, {}, {}, {}}, "the bag folder holds no .db3 file",
                           "dynpos reads rosbag2 SQLite bags (.db3) and MCAP files");
  }
  return files;
}

struct Db3Reader::State {
  std::string name;
  sqlite3* db = nullptr;
  std::vector<Db3Topic> topics;
  std::map<std::string, Db3Definition> definitions;

  ~State() { sqlite3_close(db); }

  // An error of the file from SQLite's last message.
  core::InputError sqlite_error(const std::string& what, const std::string& topic = {}) const {
    return core::InputError({name, {}, {}, topic},
                            fmt::format("{}: {}", what, db ? sqlite3_errmsg(db) : "out of memory"),
                            std::string(kDb3Hint));
  }

  void prepare(Statement& s, const std::string& sql, const std::string& what) const {
    if (sqlite3_prepare_v2(db, sql.c_str(), -1, &s.stmt, nullptr) != SQLITE_OK) {
      throw sqlite_error(what);
    }
  }

  void open(const std::filesystem::path& file) {
    if (std::FILE* f = std::fopen(file.c_str(), "rb"); f != nullptr) {
      std::fclose(f);
    } else {
      throw core::InputError({name, {}, {}, {}},
                             fmt::format("cannot open it: {}", std::strerror(errno)),
                             "check the path and its permissions");
    }
    if (!has_sqlite_magic(file)) {
      throw core::InputError({name, {}, {}, {}},
                             "not an SQLite database (it does not start with \"SQLite format 3\")",
                             "a rosbag2 .db3 file is one");
    }
    if (sqlite3_open_v2(immutable_uri(file).c_str(), &db, SQLITE_OPEN_READONLY | SQLITE_OPEN_URI,
                        nullptr) != SQLITE_OK) {
      throw sqlite_error("cannot open it");
    }
    // A file from elsewhere: no code of its schema runs, sizes are checked.
    sqlite3_db_config(db, SQLITE_DBCONFIG_DEFENSIVE, 1, nullptr);
    sqlite3_db_config(db, SQLITE_DBCONFIG_TRUSTED_SCHEMA, 0, nullptr);
    sqlite3_limit(db, SQLITE_LIMIT_LENGTH, kMaxDb3MessageBytes);
    sqlite3_exec(db, "PRAGMA cell_size_check=ON", nullptr, nullptr, nullptr);
  }

  std::map<std::string, std::string> tables() const {
    Statement s;
    prepare(s, "SELECT name, type FROM sqlite_master", "its tables");
    std::map<std::string, std::string> out;
    int rc = SQLITE_ROW;
    while ((rc = sqlite3_step(s.stmt)) == SQLITE_ROW) {
      out[column_text(s.stmt, 0)] = column_text(s.stmt, 1);
    }
    if (rc != SQLITE_DONE) throw sqlite_error("its tables");
    return out;
  }

  void check_tables(const std::map<std::string, std::string>& found) const {
    for (const char* table : {"topics", "messages"}) {
      const auto t = found.find(table);
      if (t != found.end() && t->second == "table") continue;
      std::vector<std::string> names;
      for (const auto& [n, type] : found) {
        if (type == "table") names.push_back(n);
      }
      throw core::InputError(
          {name, {}, {}, {}},
          fmt::format(
              "not a rosbag2 bag: it has no table '{}' (its tables: {})", table,
              names.empty() ? std::string("none") : fmt::format("{}", fmt::join(names, ", "))),
          std::string(kDb3Hint));
    }
  }

  void read_topics() {
    Statement s;
    prepare(s, "SELECT id, name, type, serialization_format FROM topics ORDER BY id",
            "the table topics");
    int rc = SQLITE_ROW;
    while ((rc = sqlite3_step(s.stmt)) == SQLITE_ROW) {
      topics.push_back({sqlite3_column_int64(s.stmt, 0), column_text(s.stmt, 1),
                        column_text(s.stmt, 2), column_text(s.stmt, 3)});
    }
    if (rc != SQLITE_DONE) throw sqlite_error("the table topics");
  }

  void read_definitions() {
    Statement s;
    prepare(s, "SELECT topic_type, encoding, encoded_message_definition FROM message_definitions",
            "the table message_definitions");
    int rc = SQLITE_ROW;
    while ((rc = sqlite3_step(s.stmt)) == SQLITE_ROW) {
      definitions[column_text(s.stmt, 0)] = {column_text(s.stmt, 1), column_text(s.stmt, 2)};
    }
    if (rc != SQLITE_DONE) throw sqlite_error("the table message_definitions");
  }
};

Db3Reader::Db3Reader(const std::filesystem::path& file, std::string name)
    : state_(std::make_unique<State>()) {
  state_->name = std::move(name);
  state_->open(file);
  const std::map<std::string, std::string> found = state_->tables();
  state_->check_tables(found);
  state_->read_topics();
  const auto definitions = found.find("message_definitions");
  if (definitions != found.end() && definitions->second == "table") state_->read_definitions();
}

Db3Reader::~Db3Reader() = default;
Db3Reader::Db3Reader(Db3Reader&&) noexcept = default;
Db3Reader& Db3Reader::operator=(Db3Reader&&) noexcept = default;

const std::vector<Db3Topic>& Db3Reader::topics() const noexcept { return state_->topics; }

const std::map<std::string, Db3Definition>& Db3Reader::definitions() const noexcept {
  return state_->definitions;
}

void Db3Reader::read_messages(const std::vector<std::int64_t>& topic_ids,
                              const std::function<void(const Db3Message&)>& on_message) {
  if (topic_ids.empty()) return;
  std::string sql = "SELECT id, topic_id, timestamp, data FROM messages WHERE topic_id IN (?";
  for (std::size_t i = 1; i < topic_ids.size(); ++i) sql += ",?";
  sql += ") ORDER BY timestamp";
  Statement s;
  state_->prepare(s, sql, "the table messages");
  for (std::size_t i = 0; i < topic_ids.size(); ++i) {
    sqlite3_bind_int64(s.stmt, static_cast<int>(i + 1), topic_ids[i]);
  }
  Db3Message m;
  int rc = SQLITE_ROW;
  while ((rc = sqlite3_step(s.stmt)) == SQLITE_ROW) {
    m.id = sqlite3_column_int64(s.stmt, 0);
    m.topic_id = sqlite3_column_int64(s.stmt, 1);
    if (sqlite3_column_type(s.stmt, 2) != SQLITE_INTEGER) {
      throw error(fmt::format("message id {}", m.id), "its timestamp is not an integer");
    }
    m.timestamp_ns = sqlite3_column_int64(s.stmt, 2);
    const void* data = sqlite3_column_blob(s.stmt, 3);
    const int bytes = sqlite3_column_bytes(s.stmt, 3);
    m.data = {static_cast<const std::uint8_t*>(data),
              data == nullptr ? 0U : static_cast<std::size_t>(bytes)};
    on_message(m);
  }
  if (rc != SQLITE_DONE) {
    throw state_->sqlite_error(m.id == 0
                                   ? std::string("the table messages")
                                   : fmt::format("the table messages, after message id {}", m.id));
  }
}

core::InputError Db3Reader::error(const std::string& where, const std::string& problem,
                                  const std::string& topic, const std::string& hint) const {
  return core::InputError({state_->name, {}, {}, topic},
                          where.empty() ? problem : fmt::format("at {}: {}", where, problem), hint);
}

}  // namespace dynpos::io
