#include "dynpos/live/stream_lines.hpp"

#include <utility>

#include "dynpos/core/error.hpp"
#include "dynpos/live/tag_block.hpp"

namespace dynpos::live {

StreamLines::StreamLines(std::string name, bool strict, LineSink sink)
    : name_(std::move(name)), strict_(strict), sink_(std::move(sink)) {}

void StreamLines::emit(std::string_view line) {
  ++line_number_;
  if (!line.starts_with('\\')) {
    ++counts_.lines;
    sink_(line, true);
    return;
  }
  const TaggedLine tagged = read_tag_blocks(line);
  if (tagged.status == TagBlockStatus::kValid) {
    ++counts_.tag_blocks;
    ++counts_.lines;
    sink_(tagged.sentence, true);
    return;
  }
  ++counts_.bad_tag_blocks;
  if (strict_) {
    const bool checksum = tagged.status == TagBlockStatus::kBadChecksum;
    throw core::InputError(
        {.file = name_, .line = line_number_, .column = {}, .column_name = "tag block"},
        checksum ? "tag block checksum mismatch" : "malformed tag block (no closing '\\' or *hh)",
        "without --strict such a line is dropped and counted");
  }
}

void StreamLines::add_bytes(std::string_view bytes) {
  counts_.bytes += bytes.size();
  while (!bytes.empty()) {
    const std::size_t end = bytes.find('\n');
    if (end == std::string_view::npos) {
      pending_.append(bytes);
      if (pending_.size() > kMaxLineBytes) {
        counts_.unterminated_bytes += pending_.size();
        sink_(pending_, false);
        pending_.clear();
      }
      return;
    }
    if (pending_.empty()) {
      emit(bytes.substr(0, end + 1));
    } else {
      pending_.append(bytes.substr(0, end + 1));
      emit(pending_);
      pending_.clear();
    }
    bytes.remove_prefix(end + 1);
  }
}

void StreamLines::add_datagram(std::string_view datagram) {
  ++counts_.datagrams;
  if (is_other_450_datagram(datagram)) {
    counts_.bytes += datagram.size();
    ++counts_.other_datagrams;
    return;
  }
  const std::string_view payload = strip_udpbc_header(datagram);
  counts_.bytes += datagram.size() - payload.size();
  pending_.clear();  // a datagram holds whole lines: nothing carries over
  add_bytes(payload);
  if (!pending_.empty()) {
    pending_.append("\r\n");
    emit(pending_);
    pending_.clear();
  }
}

void StreamLines::finish() {
  if (pending_.empty()) return;
  counts_.unterminated_bytes += pending_.size();
  sink_(pending_, false);
  pending_.clear();
}

}  // namespace dynpos::live
