// Internal: the balls the surface stage asks to shrink (paper 2.4), at most one radius per ball.
#pragma once

#include <algorithm>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "refinement/ball_index.hpp"

namespace vorocrust {

// A ball shrinks to 5 % inside the distance to the point it must give up. Shrinking to the
// distance itself leaves the point on the sphere: for a sliver, on four spheres, a degenerate
// seed, and a sliver's quartet is nearly degenerate anyway: the balls whose radii C3 ties to the
// shrunk one shrink with it, which moves the triplet's points by as much as the shrink. With a
// clearance of 1e-6 the same quartets came back for 60-100 rounds (cgal_joint 99, igl_bunny 59);
// with 5 % they resolve in 5-6.
inline constexpr double kShrinkClearance = 0.05;

// Per ball the smallest radius asked for, by ball index, and the largest shrinkage ratio
// (r - r') / r among them (paper 2.4, "Shrinkage Ratio").
struct BallShrinks {
  std::vector<std::pair<std::uint32_t, double>> radii;
  double max_ratio = 0;
};

// Gathers requests in any order; the result is ordered by ball index, so it does not depend on
// the order requests came in.
class BallShrinkRequests {
 public:
  void ask(std::uint32_t ball, double radius) {
    auto [it, fresh] = radius_.emplace(ball, radius);
    if (!fresh) it->second = std::min(it->second, radius);
  }
  BallShrinks result(const BallIndex& balls) const {
    BallShrinks out;
    for (const auto& [ball, r] : radius_) {
      out.radii.emplace_back(ball, r);
      out.max_ratio = std::max(out.max_ratio, (balls[ball].radius - r) / balls[ball].radius);
    }
    return out;
  }

 private:
  std::map<std::uint32_t, double> radius_;
};

}  // namespace vorocrust
