#include "capture_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>

#include "dynpos/analysis/options.hpp"
#include "dynpos/io/temporary_files.hpp"

namespace dynpos::live::detail {

CaptureFile::CaptureFile(const std::filesystem::path& path) : path_(path) {
  if (path.empty()) {
    std::string name = (std::filesystem::temp_directory_path() / "dynpos-live-XXXXXX").string();
    const io::temporary_files::Hold hold;
    const int fd = ::mkstemp(name.data());
    if (fd < 0) {
      throw analysis::option_error(
          "capture",
          "cannot create a temporary file in " + std::filesystem::temp_directory_path().string() +
              ": " + std::strerror(errno),
          "give --capture FILE, or set TMPDIR to a folder that can be written");
    }
    path_ = name;
    io::temporary_files::add(path_);
    temporary_ = true;
    file_ = ::fdopen(fd, "wb");
  } else {
    file_ = std::fopen(path.c_str(), "wb");
  }
  if (file_ == nullptr) {
    throw analysis::option_error("capture",
                                 "cannot write '" + path_.string() + "': " + std::strerror(errno));
  }
}

CaptureFile::~CaptureFile() {
  if (file_ != nullptr) std::fclose(file_);
  if (temporary_) {
    std::error_code ignored;
    std::filesystem::remove(path_, ignored);
    io::temporary_files::drop(path_);
  }
}

void CaptureFile::append(std::string_view bytes) {
  if (std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size()) {
    throw std::system_error(errno, std::generic_category(), "writing " + path_.string());
  }
  bytes_ += bytes.size();
}

void CaptureFile::flush() {
  if (std::fflush(file_) != 0) {
    throw std::system_error(errno, std::generic_category(), "writing " + path_.string());
  }
}

}  // namespace dynpos::live::detail
