#pragma once
/// \file
/// The options of `leverarm mru` as a command line gives them, as text: the MRU files as
/// NAME=FILE.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace dynpos::analysis {

/// The MRU files, NAME=FILE each, as the request's mru_log; a later NAME replaces an earlier
/// one. option_error("mru_log") for a text without its '=' or a side.
std::map<std::string, std::filesystem::path> parse_mru_logs(const std::vector<std::string>& specs);

}  // namespace dynpos::analysis
