// vorocrust/threads.hpp — bounding the worker threads the library uses.
//
// While a ThreadLimit lives, parallel stages use at most `threads` workers (0 = all cores).
// Results never depend on the thread count.
#pragma once

#include "vorocrust/api.hpp"

#include <memory>

namespace vorocrust {

class VOROCRUST_API ThreadLimit {
 public:
  explicit ThreadLimit(int threads);
  ~ThreadLimit();
  ThreadLimit(const ThreadLimit&) = delete;
  ThreadLimit& operator=(const ThreadLimit&) = delete;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace vorocrust
