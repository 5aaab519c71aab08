// Seidel's algorithm: keep the optimum of the half-spaces seen so far; a new half-space that the
// optimum violates holds the new optimum on its boundary plane, found by the same algorithm one
// dimension down over the half-spaces before it, with the unknown of the largest coefficient
// eliminated.
#include "geometry/small_lp.hpp"

#include <algorithm>
#include <cmath>

namespace vorocrust::geometry {

namespace {

// A violation below this (relative to the size of the terms) is rounding; a coefficient below
// kNegligible is a plane parallel to the unknowns left.
constexpr double kSlack = 1e-12;
constexpr double kNegligible = 1e-13;

bool violated(const HalfSpace& h, const LpVector& x, int d) {
  double ax = 0, size = std::abs(h.b);
  for (int l = 0; l < d; ++l) {
    ax += h.a[l] * x[l];
    size += std::abs(h.a[l] * x[l]);
  }
  return ax - h.b > kSlack * (1 + size);
}

std::optional<LpVector> solve_line(const LpVector& c, const HalfSpace* h, std::size_t n, double bound) {
  double lo = -bound, hi = bound;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = h[i].a[0], b = h[i].b;
    if (std::abs(a) <= kNegligible) {
      if (b < -kSlack * (1 + std::abs(b))) return std::nullopt;
      continue;
    }
    if (a > 0) hi = std::min(hi, b / a);
    else lo = std::max(lo, b / a);
  }
  LpVector x{};
  if (lo > hi) {
    if (lo - hi > kSlack * (1 + std::abs(lo) + std::abs(hi))) return std::nullopt;
    x[0] = (lo + hi) / 2;
  } else {
    x[0] = c[0] < 0 ? lo : hi;
  }
  return x;
}

// The half-space g on the plane of h, with unknown j (h's pivot) replaced by its value on the plane.
HalfSpace restrict_to(const HalfSpace& g, const HalfSpace& h, int j, int d) {
  HalfSpace r;
  const double f = g.a[j] / h.a[j];
  for (int l = 0, m = 0; l < d; ++l) {
    if (l != j) r.a[m++] = g.a[l] - f * h.a[l];
  }
  r.b = g.b - f * h.b;
  return r;
}

// One buffer per dimension for the half-spaces restricted to a plane, reused by every violation
// at that dimension: no allocation once they have grown.
class Seidel {
 public:
  explicit Seidel(double bound) : bound_(bound) {}

  std::optional<LpVector> solve(int d, const LpVector& c, const HalfSpace* h, std::size_t n) {
    if (d == 1) return solve_line(c, h, n, bound_);
    LpVector x{};
    for (int l = 0; l < d; ++l) x[l] = c[l] < 0 ? -bound_ : bound_;  // the box's best corner
    std::vector<HalfSpace>& below = below_[static_cast<std::size_t>(d)];
    for (std::size_t i = 0; i < n; ++i) {
      if (!violated(h[i], x, d)) continue;
      int j = 0;
      for (int l = 1; l < d; ++l) {
        if (std::abs(h[i].a[l]) > std::abs(h[i].a[j])) j = l;
      }
      // A plane with no unknown to solve for: 0 <= b violated, so nothing is feasible.
      if (std::abs(h[i].a[j]) <= kNegligible) return std::nullopt;
      // The box on the eliminated unknown first, then every half-space before this one.
      below.clear();
      for (double side : {1.0, -1.0}) {
        HalfSpace box;
        box.a[j] = side;
        box.b = bound_;
        below.push_back(restrict_to(box, h[i], j, d));
      }
      for (std::size_t k = 0; k < i; ++k) below.push_back(restrict_to(h[k], h[i], j, d));
      HalfSpace objective;
      objective.a = c;
      const LpVector down = restrict_to(objective, h[i], j, d).a;
      const std::optional<LpVector> y = solve(d - 1, down, below.data(), below.size());
      if (!y) return std::nullopt;
      double rest = h[i].b;
      for (int l = 0, m = 0; l < d; ++l) {
        if (l == j) continue;
        x[l] = (*y)[m++];
        rest -= h[i].a[l] * x[l];
      }
      x[j] = rest / h[i].a[j];
    }
    return x;
  }

 private:
  double bound_;
  std::array<std::vector<HalfSpace>, kMaxUnknowns + 1> below_;
};

}  // namespace

std::optional<LpVector> maximise(int unknowns, const LpVector& objective, const std::vector<HalfSpace>& constraints,
                                 double bound) {
  return Seidel(bound).solve(unknowns, objective, constraints.data(), constraints.size());
}

}  // namespace vorocrust::geometry
