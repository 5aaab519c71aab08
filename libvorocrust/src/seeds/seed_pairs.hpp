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

// The seed pairs of a set of balls that changes a little between calls, as sliver elimination
// changes it: a round shrinks a few dozen balls of a few hundred thousand and the refinement adds
// a few hundred, so only the triplets within reach of those are found again (igl_camelhead
// --smooth: 1.7 s a round for every triplet). The pairs are those find_seed_pairs gives, in
// the same order.
class KeptSeedPairs {
 public:
  // The pairs of `balls` as they are now. Balls are only added or shrunk between calls (the
  // refinement's rule), and a ball whose radius changed since the last call counts as changed.
  const SeedPairs& update(const BallIndex& balls);
  // How many balls' triplets the last update found again.
  std::size_t balls_found_again() const { return found_again_; }
  // The pairs of the last update, handed over; the next update finds every triplet again.
  SeedPairs release();

 private:
  SeedPairs pairs_;
  // Per ball p: the triplets whose smallest ball is p, as pairs_.uncovered[first_uncovered_[p],
  // first_uncovered_[p + 1]) and the same for half_covered, and their count.
  std::vector<std::size_t> first_uncovered_{0}, first_half_covered_{0};
  std::vector<std::uint32_t> triplets_;
  std::vector<double> radius_;  // each ball's radius when its triplets were found
  std::size_t found_again_ = 0;
};

// The balls overlapping ball `p` (|p - q| < r_p + r_q), ascending, without p.
void overlapping_balls(const BallIndex& balls, std::uint32_t p, std::vector<std::uint32_t>& out);

}  // namespace vorocrust
