// core/union_find.hpp — disjoint sets of 0..n-1 that several threads may unite at once.
//
// unite(a, b) merges the sets of a and b; find(a) returns its set's root, which is always the
// set's smallest element (a larger root is linked below a smaller one, by compare-and-swap), so
// the roots, like the sets, do not depend on the order or the threads of the unions.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>

namespace vorocrust {

class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(std::make_unique<std::atomic<std::uint32_t>[]>(n)) {
    for (std::size_t i = 0; i < n; ++i) parent_[i].store(static_cast<std::uint32_t>(i), std::memory_order_relaxed);
  }

  std::uint32_t find(std::uint32_t a) {
    for (;;) {
      std::uint32_t p = parent_[a].load(std::memory_order_relaxed);
      if (p == a) return a;
      const std::uint32_t g = parent_[p].load(std::memory_order_relaxed);
      // Path halving. Parents only ever decrease, so there is no cycle; a failed exchange only
      // means another thread shortened the path first.
      if (g != p) parent_[a].compare_exchange_weak(p, g, std::memory_order_relaxed);
      a = g;
    }
  }

  void unite(std::uint32_t a, std::uint32_t b) {
    for (;;) {
      a = find(a);
      b = find(b);
      if (a == b) return;
      if (a < b) std::swap(a, b);
      std::uint32_t expected = a;
      if (parent_[a].compare_exchange_strong(expected, b, std::memory_order_relaxed)) return;
    }
  }

 private:
  std::unique_ptr<std::atomic<std::uint32_t>[]> parent_;
};

}  // namespace vorocrust
