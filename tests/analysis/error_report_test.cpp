// The command line's report of the error that ended a command: the message and whether the user
// can fix it (exit 2) or it is a failure (exit 1).

#include "dynpos/analysis/error_report.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <new>
#include <stdexcept>
#include <system_error>

#include "dynpos/analysis/options.hpp"

namespace dynpos::analysis {
namespace {

template <class E>
ErrorReport report_of(const E& error, const std::vector<std::string>& arguments = {}) {
  return cli_error_report(std::make_exception_ptr(error), arguments);
}

TEST(ErrorReport, AnInputErrorIsTheUsersInTheCommandLinesSpelling) {
  const ErrorReport r = report_of(option_error("min_step", "must be > 0", "e.g. 0.1"));
  EXPECT_EQ(r.message, "(--min-step): must be > 0; e.g. 0.1");
  EXPECT_TRUE(r.input_error);
}

TEST(ErrorReport, AFileSystemErrorNamesThePathAndTheSystemsReason) {
  const std::error_code denied = std::make_error_code(std::errc::permission_denied);
  const ErrorReport r =
      report_of(std::filesystem::filesystem_error("cannot create", "out/\x1b[2Jplots", denied));
  EXPECT_EQ(r.message,
            "'out/\\x1b[2Jplots': " + denied.message() + "; check the path and its permissions");
  EXPECT_TRUE(r.input_error);
  EXPECT_EQ(report_of(std::filesystem::filesystem_error("x", denied)).message,
            denied.message() + "; check the path and its permissions");
}

TEST(ErrorReport, AThreadTheSystemWillNotStartIsTheUsersOtherSystemErrorsAreFailures) {
  const std::error_code again = std::make_error_code(std::errc::resource_unavailable_try_again);
  const ErrorReport thread = report_of(std::system_error(again, "thread"));
  EXPECT_EQ(thread.message, "the system cannot start another thread (" + again.message() +
                                "); use --jobs 1, or raise the limit of memory (ulimit -v) or "
                                "of processes");
  EXPECT_TRUE(thread.input_error);
  const std::system_error other(std::make_error_code(std::errc::io_error), "read");
  const ErrorReport failure = report_of(other);
  EXPECT_EQ(failure.message, other.what());
  EXPECT_FALSE(failure.input_error);
}

TEST(ErrorReport, OutOfMemoryNamesTheCommandLine) {
  const ErrorReport r = report_of(std::bad_alloc(), {"identify", "step", "-", "--col", "a\tb"});
  EXPECT_EQ(r.message,
            "out of memory running 'identify step - --col a\\tb'; give a shorter log or run, a "
            "window (--from/--to), fewer --jobs, or a machine with more memory");
  EXPECT_TRUE(r.input_error);
}

TEST(ErrorReport, AnyOtherErrorIsAFailureShownAsText) {
  const ErrorReport r = report_of(std::logic_error("bad \x07state"));
  EXPECT_EQ(r.message, "bad \\x07state");
  EXPECT_FALSE(r.input_error);
}

TEST(ErrorReport, AnErrorThatIsNoStdExceptionIsRethrown) {
  EXPECT_THROW(cli_error_report(std::make_exception_ptr(42), {}), int);
}

}  // namespace
}  // namespace dynpos::analysis
