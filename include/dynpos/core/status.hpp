#pragma once
/// \file
/// The one outcome convention of every analysis: a status, a message and warnings as data.
///
/// An analysis never aborts on data it cannot use well: a fit that did not converge or a step
/// that could not be fitted comes back with a status and a reason for the caller (CLI, report,
/// Python) to show. Bad input (files, options) throws core::InputError instead.

#include <string>
#include <string_view>

namespace dynpos::core {

/// Overall outcome of an estimate, a fit or a whole analysis.
enum class Status {
  kOk,            ///< estimates are present (they may still carry warnings)
  kNotConverged,  ///< an iteration limit was hit; estimates are the last iterate
  kFailed,        ///< no estimate could be made; the message says why
};

/// Short stable identifier for JSON: "ok", "not_converged", "failed".
std::string_view status_name(Status status);

}  // namespace dynpos::core
