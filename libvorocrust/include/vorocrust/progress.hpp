// vorocrust/progress.hpp — how long operations report progress and are cancelled.
//
// A callback receives the current phase and the fraction of it done (negative when unknown).
// Returning false asks the library to stop: the operation then throws Error(Cancelled) at its
// next check, writing nothing. Callbacks are invoked from the calling thread only.
#pragma once

#include "vorocrust/api.hpp"

#include <functional>
#include <string_view>

namespace vorocrust {

struct VOROCRUST_API ProgressUpdate {
  std::string_view phase;
  double fraction = -1.0;
};

using ProgressCallback = std::function<bool(const ProgressUpdate&)>;

}  // namespace vorocrust
