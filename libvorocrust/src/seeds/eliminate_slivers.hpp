// Internal: sliver elimination (paper 2.4). Shrinks balls until no triplet of overlapping balls
// has a half-covered seed pair, running the refinement again after each round so C1-C4 hold.
// Once no pair is half-covered, rounds that part near-twin seeds (seeds/near_twins.hpp) follow,
// then, with an angle bound, rounds that shrink balls about skinny surface triangles
// (seeds/skinny_triangles.hpp), each followed by sliver elimination again.
#pragma once

#include "refinement/refine_balls.hpp"
#include "seeds/ball_shrinks.hpp"
#include "seeds/seed_pairs.hpp"
#include "vorocrust/stats.hpp"

namespace vorocrust {

struct SliverOptions {
  // Paper 2.4. Counted from the first sliver round, across the rounds between that split or
  // part balls: each of those brings sliver rounds of its own, and counted only since the last
  // of them, safe mode never came where each brought dozens (igl_camelhead --smooth
  // --smoothing-iterations 2: 387 sliver rounds, 14 minutes; 267 and 7.5 minutes with safe mode
  // from round 100).
  int iterations_before_safe_mode = 100;
  int max_iterations = 400;  // a guard on the guard: safe mode converges long before
  // Surface triangles of patch balls with an angle below this are split (0: none is).
  double min_triangle_angle_degrees = 0;
  // Rounds of that at most: each round can make a few skinny triangles of its own, so the
  // rounds are bounded rather than run until none is left (igl_bunny --smooth: 400 skinny
  // triangles, then 198, 134, 88, 58, 44, 19, 11, 6, 1).
  int max_skinny_triangle_rounds = 10;
  // Rounds that part near-twin seeds (seeds/near_twins.hpp) at most; twins left after them are
  // merged into one seed by surface_seeds. Parting one pair can bring others: few, not none.
  int max_near_twin_rounds = 10;
};

// Returns the seed pairs of the final balls, none of them half-covered.
SeedPairs eliminate_slivers(BallRefinement& refinement, const SliverOptions& options, const ProgressCallback& progress,
                            SliverStats& stats);

// For each half-covered pair, the one shrink among its quartets that needs the least shrinkage
// ratio; per ball the smallest radius so assigned.
BallShrinks choose_sliver_shrinks(const BallIndex& balls, const std::vector<HalfCoveredPair>& half_covered);

}  // namespace vorocrust
