// The library's progress reports, passed on to MeshLab's progress callback.
#pragma once

#include <wrap/callback.h>

#include <algorithm>
#include <chrono>
#include <string>

#include "vorocrust/progress.hpp"

namespace vorocrust::meshlab {

// A ProgressCallback that shows "VoroCrust: PHASE" with the phase's percentage (0 while the
// library does not know it) through MeshLab's callback: at each new phase, and otherwise at most
// every quarter second while the percentage moves (meshlabserver prints every call, and MeshLab's
// window processes its events in each). A callback answering false cancels the run: the library
// then throws Error(Cancelled). No callback: no reports.
inline ProgressCallback progress_to(vcg::CallBackPos* cb) {
  if (cb == nullptr) return {};
  using Clock = std::chrono::steady_clock;
  return [cb, last_phase = std::string(), last_percent = -1,
          last_call = Clock::time_point()](const ProgressUpdate& update) mutable {
    const int percent = update.fraction < 0 ? 0 : std::clamp(static_cast<int>(update.fraction * 100), 0, 100);
    const Clock::time_point now = Clock::now();
    if (update.phase == last_phase &&
        (percent == last_percent || now - last_call < std::chrono::milliseconds(250))) {
      return true;
    }
    last_phase = update.phase;
    last_percent = percent;
    last_call = now;
    const std::string text = "VoroCrust: " + last_phase;
    return cb(percent, text.c_str());
  };
}

}  // namespace vorocrust::meshlab
