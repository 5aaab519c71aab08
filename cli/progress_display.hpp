// A progress bar on a terminal, plain "phase ... done" lines otherwise, nothing when quiet.
// It also turns Ctrl-C into a cancellation request, so an interrupted run writes nothing half-done.
#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "vorocrust/mesher.hpp"
#include "vorocrust/progress.hpp"

namespace vorocrust::cli {

class ProgressDisplay {
 public:
  explicit ProgressDisplay(bool quiet);
  ~ProgressDisplay();

  // Starts a phase the CLI runs itself (reading, validating); ends the previous one.
  void begin(const std::string& phase);
  // Ends the current phase and records its time.
  void finish();
  // The callback handed to the library; it also reports the library's own phases.
  ProgressCallback callback();

  const std::vector<PhaseTiming>& timings() const { return timings_; }

 private:
  bool update(const ProgressUpdate& update);
  void draw(double fraction);

  bool quiet_;
  bool terminal_;
  std::string phase_;
  std::chrono::steady_clock::time_point phase_start_;
  std::chrono::steady_clock::time_point last_draw_;
  std::vector<PhaseTiming> timings_;
};

}  // namespace vorocrust::cli
