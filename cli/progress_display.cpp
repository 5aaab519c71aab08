#include "progress_display.hpp"

#include <unistd.h>

#include <csignal>
#include <cstdio>

namespace vorocrust::cli {

namespace {

volatile std::sig_atomic_t interrupted = 0;
extern "C" void on_interrupt(int) { interrupted = 1; }

}  // namespace

ProgressDisplay::ProgressDisplay(bool quiet) : quiet_(quiet), terminal_(::isatty(STDERR_FILENO) != 0) {
  std::signal(SIGINT, on_interrupt);
}

ProgressDisplay::~ProgressDisplay() { std::signal(SIGINT, SIG_DFL); }

void ProgressDisplay::begin(const std::string& phase) {
  finish();
  phase_ = phase;
  phase_start_ = std::chrono::steady_clock::now();
  if (quiet_) return;
  if (terminal_) {
    draw(0.0);
  } else {
    std::fprintf(stderr, "vorocrust: %s ...\n", phase_.c_str());
  }
}

void ProgressDisplay::finish() {
  if (phase_.empty()) return;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - phase_start_).count();
  timings_.push_back({phase_, seconds});
  if (!quiet_) {
    if (terminal_) std::fprintf(stderr, "\r\033[K");
    std::fprintf(stderr, "vorocrust: %s done in %.3f s\n", phase_.c_str(), seconds);
  }
  phase_.clear();
}

ProgressCallback ProgressDisplay::callback() {
  return [this](const ProgressUpdate& u) { return update(u); };
}

bool ProgressDisplay::update(const ProgressUpdate& u) {
  if (u.phase != phase_) begin(std::string(u.phase));
  if (!quiet_ && terminal_) {
    const auto now = std::chrono::steady_clock::now();
    if (now - last_draw_ > std::chrono::milliseconds(100)) {
      last_draw_ = now;
      draw(u.fraction);
    }
  }
  return interrupted == 0;
}

void ProgressDisplay::draw(double fraction) {
  constexpr int kWidth = 30;
  char bar[kWidth + 1];
  const int filled = fraction < 0 ? 0 : static_cast<int>(fraction * kWidth + 0.5);
  for (int i = 0; i < kWidth; ++i) bar[i] = i < filled ? '#' : '.';
  bar[kWidth] = 0;
  if (fraction < 0) {
    std::fprintf(stderr, "\r\033[K[%s] %s", bar, phase_.c_str());
  } else {
    std::fprintf(stderr, "\r\033[K[%s] %3d%% %s", bar, static_cast<int>(fraction * 100 + 0.5), phase_.c_str());
  }
  std::fflush(stderr);
}

}  // namespace vorocrust::cli
