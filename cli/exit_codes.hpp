// The CLI's exit codes: one per class of failure, so scripts can tell them apart.
#pragma once

#include "vorocrust/error.hpp"

namespace vorocrust::cli {

enum ExitCode : int {
  kOk = 0,
  kInternalError = 1,
  kUsage = 2,
  kUnreadableInput = 3,
  kInvalidGeometry = 4,
  kOutputError = 5,
  kNotImplemented = 6,
  kCancelled = 7,
  kConditionsViolated = 8,  // check-balls found balls that break a ball condition
};

inline int exit_code_for(Error::Kind kind) {
  switch (kind) {
    case Error::Kind::Usage: return kUsage;
    case Error::Kind::UnreadableInput: return kUnreadableInput;
    case Error::Kind::InvalidGeometry: return kInvalidGeometry;
    case Error::Kind::Output: return kOutputError;
    case Error::Kind::Cancelled: return kCancelled;
    case Error::Kind::NotImplemented: return kNotImplemented;
    case Error::Kind::Internal: return kInternalError;
  }
  return kInternalError;
}

inline constexpr const char* kExitCodeHelp =
    "Exit codes: 0 success, 1 internal error, 2 usage error, 3 unreadable input, 4 invalid geometry, "
    "5 cannot write output, 6 not yet implemented, 7 cancelled, 8 ball conditions violated (check-balls).";

}  // namespace vorocrust::cli
