// Internal: sliver elimination (paper 2.4). Shrinks balls until no triplet of overlapping balls
// has a half-covered seed pair, running the refinement again after each round so C1-C4 hold.
#pragma once

#include "refinement/refine_balls.hpp"
#include "seeds/seed_pairs.hpp"
#include "vorocrust/mesher.hpp"

namespace vorocrust {

struct SliverOptions {
  int iterations_before_safe_mode = 100;  // paper 2.4
  int max_iterations = 400;               // a guard on the guard: safe mode converges long before
};

// Returns the seed pairs of the final balls, none of them half-covered.
SeedPairs eliminate_slivers(BallRefinement& refinement, const SliverOptions& options, const ProgressCallback& progress,
                            SliverStats& stats);

// For each half-covered pair, the one shrink among its quartets that needs the least shrinkage
// ratio; per ball the smallest radius so assigned. Returns (ball, radius) pairs by ball index
// and the largest shrinkage ratio among them.
struct SliverShrinks {
  std::vector<std::pair<std::uint32_t, double>> radii;
  double max_ratio = 0;
};
SliverShrinks choose_sliver_shrinks(const BallIndex& balls, const std::vector<HalfCoveredPair>& half_covered);

}  // namespace vorocrust
