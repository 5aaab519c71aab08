// Internal: near-twin seeds (paper 2.4) and the shrinks that part them.
//
// Where four balls' spheres nearly pass through one point, two triplets sharing two balls have
// points there a hair apart, neither inside the other's fourth ball: both pairs are uncovered and
// valid, but the Voronoi cells of such seeds split along a plane through nearly coincident
// vertices. Keeping both can leave cells that do not assemble (cgal_bones: seeds 4.2e-5 radii
// apart); dropping one (surface_seeds) leaves its pair's facet in the surface with no cell face
// under it, so the cells' boundary is no longer the surface (igl_bunny: 127 086 boundary faces
// for 127 080 triangles; sandia_bracket: 13 483 for 13 484).
//
// The two points lie on the circle where the shared balls' spheres meet, each where one of the
// unshared balls' spheres crosses it, and the arcs those two balls cover end there without
// overlapping. Shrinking one unshared ball retracts its arc: its point moves away from the other
// along the circle and stays outside the other's ball, so both pairs stay uncovered, farther apart.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "refinement/ball_index.hpp"
#include "seeds/ball_shrinks.hpp"
#include "seeds/seed_pairs.hpp"

namespace vorocrust {

// Points of two seed pairs nearer each other than this, in their triplets' mean radius, are twins.
inline constexpr double kTwin = 1e-4;

// The pairs (i < j) of `points` nearer each other than kTwin times the radius of either (a pair
// counts when either point reaches the other), ascending.
std::vector<std::pair<std::uint32_t, std::uint32_t>> twin_pairs(const std::vector<Point>& points,
                                                                 const std::vector<double>& radii);

struct TwinShrinks {
  std::size_t twins = 0;  // pairs of points of different seed pairs nearer than kTwin radii
  BallShrinks shrinks;
};

// The twins among the points of `pairs` and, for each, the larger of the two balls the triplets
// do not share shrunk to (1 - kShrinkClearance) of its radius (where the triplets share fewer
// than two balls, the largest ball that is not in both). Ordered by ball index.
TwinShrinks choose_twin_shrinks(const BallIndex& balls, const std::vector<SeedPair>& pairs);

}  // namespace vorocrust
