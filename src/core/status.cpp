#include "dynpos/core/status.hpp"

namespace dynpos::core {

std::string_view status_name(Status status) {
  switch (status) {
    case Status::kOk:
      return "ok";
    case Status::kNotConverged:
      return "not_converged";
    case Status::kFailed:
      return "failed";
  }
  return "unknown";
}

}  // namespace dynpos::core
