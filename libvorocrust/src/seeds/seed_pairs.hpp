// Internal: the seed pairs of every triplet of overlapping balls (paper 2.4), sorted into the
// pairs that give two seeds and the half-covered ones that signal a sliver.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "refinement/ball_index.hpp"

namespace vorocrust {

struct SeedPair {
  std::array<std::uint32_t, 3> balls;  // ascending ball indices
  std::array<Point, 2> points;         // points[0] on the side the triangle of the centres faces
};

// The mean radius of a pair's triplet: the size its seeds carry, and the scale near twins are
// measured in.
double mean_radius(const BallIndex& balls, const SeedPair& pair);

// A triplet with exactly one of its two points inside a fourth ball.
struct HalfCoveredPair {
  SeedPair pair;
  int covered = 0;                    // which of pair.points is covered
  std::vector<std::uint32_t> fourth;  // every other ball holding either point
};

struct SeedPairs {
  std::vector<SeedPair> uncovered;  // both points free: two seeds across one surface facet
  std::vector<HalfCoveredPair> half_covered;
  std::size_t triplets = 0;  // triplets whose spheres meet in two points
};

// Every triplet of mutually overlapping balls once. A point counts as covered when it lies in
// the interior of a fourth ball. The result is ordered by ball indices, whatever the number of
// threads.
SeedPairs find_seed_pairs(const BallIndex& balls);

// The balls overlapping ball `p` (|p - q| < r_p + r_q), ascending, without p.
void overlapping_balls(const BallIndex& balls, std::uint32_t p, std::vector<std::uint32_t>& out);

}  // namespace vorocrust
