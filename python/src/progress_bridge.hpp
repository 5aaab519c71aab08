// The library's progress reports, passed on to a Python callback.
#pragma once

#include <chrono>
#include <optional>
#include <string>

#include "bindings.hpp"

namespace vorocrust::python {

// A ProgressCallback for a run that holds no GIL. At each new phase, and otherwise at most every
// `interval` within one, it takes the GIL and calls `callback(phase, fraction)` (fraction None
// when unknown); between calls it answers without touching Python, as the library reports many
// times a second. The run is cancelled (the library then throws Error(Cancelled)) when the
// callback returns a false value other than None, when it raises, and on a pending signal such
// as Ctrl-C; the Python exception is kept for rethrow(). Without a callback only signals are
// checked. Calls come from the thread that started the run (progress.hpp).
class ProgressBridge {
 public:
  explicit ProgressBridge(py::object callback, std::chrono::milliseconds interval = std::chrono::milliseconds(50))
      : callback_(std::move(callback)), interval_(interval) {}
  ProgressBridge(const ProgressBridge&) = delete;
  ProgressBridge& operator=(const ProgressBridge&) = delete;

  ProgressCallback callback() {
    return [this](const ProgressUpdate& update) { return report(update); };
  }

  // After the run threw Error(Cancelled): raises the Python exception that stopped it, if any.
  void rethrow() {
    if (error_) {
      py::error_already_set error = std::move(*error_);
      error_.reset();
      throw error;
    }
  }

 private:
  using Clock = std::chrono::steady_clock;

  bool report(const ProgressUpdate& update) {
    const Clock::time_point now = Clock::now();
    if (update.phase == phase_ && now - last_call_ < interval_) return true;
    phase_ = update.phase;
    last_call_ = now;
    py::gil_scoped_acquire gil;
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (callback_.is_none()) return true;
      const py::object answer =
          callback_(phase_, update.fraction < 0 ? py::object(py::none()) : py::object(py::float_(update.fraction)));
      return answer.is_none() || py::bool_(answer);
    } catch (py::error_already_set& e) {
      error_.emplace(std::move(e));
      return false;
    }
  }

  py::object callback_;
  std::chrono::milliseconds interval_;
  std::string phase_;
  Clock::time_point last_call_;
  std::optional<py::error_already_set> error_;
};

}  // namespace vorocrust::python
