#include "capture_lines.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "dynpos/core/error.hpp"

namespace dynpos::io::detail {

bool CaptureLines::fill() {
  if (in_.eof() || in_.bad()) return false;
  in_.read(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  pos_ = 0;
  end_ = static_cast<std::size_t>(in_.gcount());
  taken_ += end_;
  if (first_) {
    first_ = false;
    if (end_ >= 3 && buffer_[0] == '\xEF' && buffer_[1] == '\xBB' && buffer_[2] == '\xBF') pos_ = 3;
  }
  if (in_.fail() && !in_.bad()) in_.clear(in_.rdstate() & ~std::ios::failbit);
  return pos_ < end_;
}

std::size_t CaptureLines::take(std::string* out, std::size_t room) {
  const char* begin = buffer_.data() + pos_;
  const char* end = buffer_.data() + end_;
  const char* stop = std::find_if(begin, end, [](char c) { return c == '\n' || c == '\r'; });
  const auto text = static_cast<std::size_t>(stop - begin);
  if (out != nullptr) out->append(begin, std::min(text, room));
  pos_ += text;
  ended_ = stop != end;
  if (ended_) {
    after_cr_ = *stop == '\r';
    ++pos_;
  }
  return text;
}

LineStatus CaptureLines::next(std::string& out, std::size_t max_bytes) {
  out.clear();
  ended_ = false;
  bool any = false;
  for (;;) {
    if (pos_ == end_ && !fill()) return any ? LineStatus::kLine : LineStatus::kEnd;
    if (after_cr_) {
      after_cr_ = false;
      if (buffer_[pos_] == '\n') {  // the end of the line before, "\r\n"
        ++pos_;
        continue;
      }
    }
    any = true;
    const std::size_t room = max_bytes - out.size();
    if (take(&out, room) > room) return LineStatus::kTooLong;
    if (ended_) return LineStatus::kLine;
  }
}

bool CaptureLines::skip_rest(std::size_t max_bytes) {
  for (std::size_t skipped = 0; !ended_;) {
    if (pos_ == end_ && !fill()) return true;  // the end of the stream
    skipped += take(nullptr, 0);
    if (!ended_ && skipped > max_bytes) return false;
  }
  return true;
}

void throw_no_line_end(const std::string& file, std::size_t line, std::size_t max_bytes) {
  throw core::InputError(
      {file, line, {}, {}},
      fmt::format("no line end within {} MiB: not a text capture", max_bytes >> 20),
      "give a capture of NMEA sentences, one a line");
}

}  // namespace dynpos::io::detail
