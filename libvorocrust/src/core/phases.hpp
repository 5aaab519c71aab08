// Internal: the phases of a run, each announced, checked for cancelling and timed in one place.
//
// phases("features", work) tells the progress callback that the phase begins (it may ask to stop:
// Error(Cancelled) is thrown before the work starts), runs work() and appends its wall time to
// the run's timings under the phase's name; it returns what work returns. A phase that runs
// several times (a repair round) has several entries.
#pragma once

#include <chrono>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/memory.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/progress.hpp"
#include "vorocrust/stats.hpp"

namespace vorocrust {

class Phases {
 public:
  Phases(std::vector<PhaseTiming>& timings, const ProgressCallback& progress) : timings_(timings), progress_(progress) {}

  template <class Work>
  auto operator()(std::string_view name, Work&& work) {
    announce(name);
    const auto start = std::chrono::steady_clock::now();
    const auto record = [&] {
      timings_.push_back({std::string(name), std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                          peak_resident_bytes()});
    };
    if constexpr (std::is_void_v<decltype(work())>) {
      work();
      record();
    } else {
      auto result = work();
      record();
      return result;
    }
  }

  // Tells the callback that `name` begins; throws Error(Cancelled) when it asks to stop.
  void announce(std::string_view name) const {
    if (progress_ && !progress_({name, -1})) throw Error(Error::Kind::Cancelled, "cancelled");
  }

  const ProgressCallback& progress() const { return progress_; }

 private:
  std::vector<PhaseTiming>& timings_;
  const ProgressCallback& progress_;
};

}  // namespace vorocrust
