#include "dynpos/analysis/error_report.hpp"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <filesystem>
#include <new>
#include <system_error>

#include "dynpos/analysis/option_spelling.hpp"
#include "dynpos/core/error.hpp"

namespace dynpos::analysis {

ErrorReport cli_error_report(const std::exception_ptr& error,
                             const std::vector<std::string>& arguments) {
  try {
    std::rethrow_exception(error);
  } catch (const core::InputError& e) {
    return {cli_message(e), true};
  } catch (const std::filesystem::filesystem_error& e) {
    // A folder or file of the outputs that cannot be made or written (or an input that cannot
    // be read): the path and the system's reason, not the library's wording.
    const std::string path =
        e.path1().empty() ? std::string() : "'" + core::printable(e.path1().string()) + "': ";
    return {fmt::format("{}{}; check the path and its permissions", path, e.code().message()),
            true};
  } catch (const std::system_error& e) {
    if (e.code() != std::errc::resource_unavailable_try_again) {
      return {core::printable(e.what()), false};
    }
    // A thread the system would not start (a limit of memory or processes) where no fewer
    // threads would do.
    return {fmt::format("the system cannot start another thread ({}); use --jobs 1, or raise "
                        "the limit of memory (ulimit -v) or of processes",
                        e.code().message()),
            true};
  } catch (const std::bad_alloc&) {
    // The machine's memory ran out: what the input or the options asked for (a log, a window,
    // a run length) was too much for it. Runs are checked before they start where their size
    // is known (simulate); this is the rest.
    return {fmt::format("out of memory running '{}'; give a shorter log or run, a window "
                        "(--from/--to), fewer --jobs, or a machine with more memory",
                        core::printable(fmt::format("{}", fmt::join(arguments, " ")))),
            true};
  } catch (const std::exception& e) {
    return {core::printable(e.what()), false};
  }
}

}  // namespace dynpos::analysis
