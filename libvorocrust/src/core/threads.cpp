#include "vorocrust/threads.hpp"

#include <tbb/global_control.h>

namespace vorocrust {

struct ThreadLimit::Impl {
  std::unique_ptr<tbb::global_control> control;
};

ThreadLimit::ThreadLimit(int threads) : impl_(std::make_unique<Impl>()) {
  if (threads > 0) {
    impl_->control = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                           static_cast<std::size_t>(threads));
  }
}

ThreadLimit::~ThreadLimit() = default;

}  // namespace vorocrust
